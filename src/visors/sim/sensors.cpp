#include "visors/sim/sensors.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "visors/sim/navigation_message.hpp"

namespace visors::sim {
namespace {

core::Result<GpsReceiver> make_receiver(const CampaignScenario& s, const GpsWorld& gps, const TruthSpacecraft& truth) {
  GpsReceiverSettings settings = s.gnss.receiver;
  settings.klobuchar = gps.nav.ionosphere.value_or(gnss::KlobucharCoefficients{});
  settings.epoch_interval_s = s.step_s;  // clock_step_sigma_m is per epoch
  settings.phase_center_error_body_m = truth.geometry->phase_center_error_body_m();
  auto receiver = GpsReceiver::create(settings, RandomStream(s.seed, std::string(truth.name) + ".gps"));
  if (!receiver.ok()) return core::Error{"gnss.receiver." + receiver.error().field, receiver.error().message};
  return receiver;
}

}  // namespace

Sensors::Sensors(const CampaignScenario& scenario, std::optional<GpsWorld> gps)
    : lrf_(scenario.gnss.lrf),
      step_s_(scenario.step_s),
      half_refresh_s_(0.5 * scenario.gnss.broadcast_errors.refresh_s),
      gps_(std::move(gps)),
      lrf_rng_(scenario.seed, "osc.lrf") {
  if (gps_) sets_by_prn_ = data_sets_by_prn(gps_->satellites->broadcast_records());
}

core::Result<Sensors> Sensors::create(const CampaignScenario& scenario, const TruthWorld& truth, std::optional<GpsWorld> gps) {
  Sensors sensors(scenario, std::move(gps));
  for (std::size_t k = 0; k < 2; ++k) {
    SpacecraftSensors& c = sensors.craft_[k];
    const std::string prefix(truth[k].name);
    if (sensors.gps_) {
      auto receiver = make_receiver(scenario, *sensors.gps_, truth[k]);
      if (!receiver.ok()) return receiver.error();
      c.receiver.emplace(std::move(receiver).value());
    }
    auto clock = HostClock::create(scenario.host_clock, RandomStream(scenario.seed, prefix + ".clock"));
    if (!clock.ok()) return core::Error{"clock." + clock.error().field, clock.error().message};
    c.clock.emplace(std::move(clock).value());
    c.navigation.emplace(scenario.navigation, RandomStream(scenario.seed, prefix + ".navigation"));
  }
  return sensors;
}

EpochFrame Sensors::frame(core::GpsTime t) { return gps_ ? epoch_frame(*gps_, t, earth_frame_) : EpochFrame{}; }

// The receiver's epoch at t in the true pose (the attitude's rate from the spacecraft's commanded
// attitude law), and the broadcast record it decoded; nothing in a data gap.
std::optional<gnc::GpsMessage> Sensors::measure_gps(std::size_t k, const TruthSpacecraft& truth, const EpochFrame& frame,
                                                    core::GpsTime t, double t_s, NavigationScore& score) {
  // The target's direction held over the rate's differencing interval (it turns ~1e-11 rad there).
  const auto law = [&](double at_s, const Eigen::Vector3d& r, const Eigen::Vector3d& velocity) {
    return truth.attitude->body_to_gcrf(at_s, r, velocity, truth.target_unit_gcrf);
  };
  const Eigen::Vector3d omega_gcrf = attitude_rate_gcrf(law, t_s, truth.x_gcrf);
  const ReceiverPose pose = receiver_pose(frame, t, truth.x_gcrf, truth.q_body_to_gcrf, omega_gcrf, truth.geometry->com_body_m());
  const GpsReceiverEpoch& epoch = craft_[k].receiver->measure(pose, *gps_->satellites);
  score.record_phase_truth(truth.id, epoch);
  if (!epoch.recorded) return std::nullopt;
  gnc::GpsMessage message;
  message.t = epoch.measurement.t;
  message.epoch = epoch.measurement;
  decode_ephemeris(k, t, message);
  return message;
}

// At most one broadcast record per message: of the first tracked satellite whose data set in
// force at t (each from t_oe - refresh_s / 2, the first from the start: the receivers of
// gnss-sim select the same way) the receiver has not passed on yet and has decoded by t: its
// subframes 1-3 received whole since the later of the lock and the set's first broadcast
// (sim/navigation_message.hpp: 18-36 s).
void Sensors::decode_ephemeris(std::size_t k, core::GpsTime t, gnc::GpsMessage& message) {
  const auto records = gps_->satellites->broadcast_records();
  for (int c = 0; c < message.epoch.channel_count; ++c) {
    const auto& channel = message.epoch.channels[static_cast<std::size_t>(c)];
    const auto prn = static_cast<std::size_t>(channel.prn);
    std::size_t& next = craft_[k].next_ephemeris[prn];
    const auto set = newly_decoded_data_set(records, sets_by_prn_[prn], t, half_refresh_s_, channel.lock_time_s, next);
    if (!set) continue;
    message.has_ephemeris = true;
    message.ephemeris = records[sets_by_prn_[prn][*set]];
    next = *set + 1;
    return;
  }
}

// The OSC's rangefinder while its component powers it, inside an observation window, every
// [gnss.lrf] interval_s from the window's first step: the range between the true payload points
// with [gnss.lrf] bias_m and N(0, sigma_m) noise (as gnss-sim's lrf.csv).
std::optional<gnc::LaserRange> Sensors::measure_range(const TruthWorld& truth, core::GpsTime t, double t_s, std::int64_t step,
                                                      bool powered) {
  if (!powered) return std::nullopt;
  const auto stride = std::max<std::int64_t>(1, std::llround(lrf_.interval_s / step_s_));
  for (const ObservationWindow& w : truth[1].attitude->windows()) {
    if (t_s < w.start_s - 1e-9 || t_s > w.end_s + 1e-9) continue;
    const auto first = static_cast<std::int64_t>(std::ceil(w.start_s / step_s_ - 1e-9));
    if ((step - first) % stride != 0) return std::nullopt;
    const double range_m = (truth[1].payload_gcrf_m() - truth[0].payload_gcrf_m()).norm();
    return gnc::LaserRange{t, range_m + lrf_.bias_m + lrf_rng_.normal(lrf_.sigma_m)};
  }
  return std::nullopt;
}

gnc::NavigationSolution Sensors::ideal_solution(std::size_t k, core::GpsTime t, const TruthWorld& truth, double dt_s) {
  return craft_[k].navigation->solve(t, truth[0].x_gcrf, truth[1].x_gcrf, dt_s);
}

}  // namespace visors::sim
