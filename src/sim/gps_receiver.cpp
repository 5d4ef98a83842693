#include "sim/gps_receiver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "core/geodetic.hpp"
#include "gnss/gps_constants.hpp"

namespace visors::sim {

core::Result<bool> GpsReceiverSettings::validate() const {
  const struct {
    const char* name;
    double value;
  } non_negative[] = {{"code_sigma_m", code_sigma_m},
                      {"phase_sigma_m", phase_sigma_m},
                      {"doppler_sigma_hz", doppler_sigma_hz},
                      {"clock_step_sigma_m", clock_step_sigma_m},
                      {"initial_clock_sigma_m", initial_clock_sigma_m},
                      {"phase_center_offset_m", phase_center_offset_m},
                      {"mounting_sigma_rad", mounting_sigma_rad},
                      {"occultation_altitude_m", occultation_altitude_m}};
  for (const auto& f : non_negative) {
    if (!(std::isfinite(f.value) && f.value >= 0.0)) return core::Error{f.name, "must be finite and >= 0"};
  }
  if (!(std::abs(elevation_mask_rad) < 0.5 * core::kPi)) return core::Error{"elevation_mask_rad", "must be in (-pi/2, pi/2)"};
  if (channels < 1 || channels > gnss::kMaxGpsChannels) return core::Error{"channels", "must be in 1..12"};
  if (!(cycle_slip_probability >= 0.0 && cycle_slip_probability <= 1.0)) {
    return core::Error{"cycle_slip_probability", "must be in [0, 1]"};
  }
  if (max_slip_cycles < 1) return core::Error{"max_slip_cycles", "must be >= 1"};
  if (!antenna_body_m.allFinite()) return core::Error{"antenna_body_m", "must be finite"};
  if (!(topside.topside_fraction >= 0.0 && topside.topside_fraction <= 1.0)) {
    return core::Error{"topside.topside_fraction", "must be in [0, 1]"};
  }
  for (std::size_t k = 0; k < 4; ++k) {
    if (!std::isfinite(klobuchar.alpha[k]) || !std::isfinite(klobuchar.beta[k])) {
      return core::Error{"klobuchar", "alpha and beta must be finite"};
    }
  }
  return true;
}

namespace {

// The satellite at transmission, in the Earth-fixed axes of the reception time.
struct SignalPath {
  gnss::GpsSatelliteState satellite;  // at the transmission time, its own Earth-fixed axes
  Eigen::Vector3d r_satellite_m;      // rotated to the reception-time axes [m]
  Eigen::Vector3d v_satellite_mps;    // likewise [m/s]
  double range_m = 0.0;
};

// tau = |R3(w_E tau) r^j(t_r - tau) - r_r| / c by fixed-point iteration (contraction ~ v/c).
SignalPath trace(const GpsSatelliteTruth& satellites, std::size_t index, core::GpsTime t_receive,
                 const Eigen::Vector3d& r_receiver_m) {
  SignalPath path;
  double tau = 0.075;  // [s], a typical LEO-GPS light time
  for (int iteration = 0; iteration < 3; ++iteration) {
    path.satellite = satellites.true_state(index, t_receive - tau);
    const double angle = gnss::kGpsEarthRate * tau;
    const double c = std::cos(angle), s = std::sin(angle);
    const Eigen::Vector3d& r = path.satellite.r_ecef_m;
    const Eigen::Vector3d& v = path.satellite.v_ecef_mps;
    path.r_satellite_m = {c * r.x() + s * r.y(), -s * r.x() + c * r.y(), r.z()};
    path.v_satellite_mps = {c * v.x() + s * v.y(), -s * v.x() + c * v.y(), v.z()};
    path.range_m = (path.r_satellite_m - r_receiver_m).norm();
    tau = path.range_m / gnss::kGpsSpeedOfLight;
  }
  return path;
}

// Height above a sphere of the equatorial radius of the lowest point of the segment r -> r + L e.
double grazing_height_m(const Eigen::Vector3d& r, const Eigen::Vector3d& e, double length) {
  const double along = std::clamp(-r.dot(e), 0.0, length);
  return (r + along * e).norm() - core::kWgs84SemiMajorAxis;
}

}  // namespace

core::Result<GpsReceiver> GpsReceiver::create(const GpsReceiverSettings& settings, RandomStream rng) {
  if (auto valid = settings.validate(); !valid) return valid.error();
  GpsReceiver receiver(settings, std::move(rng));
  const double tilt_x = receiver.rng_.normal(settings.mounting_sigma_rad);
  const double tilt_y = receiver.rng_.normal(settings.mounting_sigma_rad);
  receiver.boresight_body_ = (Eigen::AngleAxisd(tilt_y, Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(tilt_x, Eigen::Vector3d::UnitX()) * Eigen::Vector3d::UnitZ())
                                 .normalized();
  receiver.epoch_.receiver_phase_cycles = receiver.rng_.uniform();
  receiver.clock_m_ = receiver.rng_.normal(settings.initial_clock_sigma_m);
  return receiver;
}

std::int64_t GpsReceiver::draw_ambiguity() {
  // An arbitrary integer in [-2^20, 2^20): a receiver starts the phase count anywhere.
  return static_cast<std::int64_t>(std::floor(rng_.uniform() * 2097152.0)) - 1048576;
}

// The antenna at the true reception time t_r = t - dt_r, and the local axes of its geodetic
// position (the Klobuchar model's azimuth and elevation are measured in them).
struct GpsReceiver::Reception {
  core::GpsTime t_receive;
  Eigen::Vector3d r_apc;      // phase centre, Earth-fixed [m]
  Eigen::Vector3d v_apc;      // [m/s]
  Eigen::Vector3d boresight;  // true boresight, Earth-fixed (unit)
  core::GeodeticPosition where;
  Eigen::Vector3d east, north, up;
};

const GpsReceiverEpoch& GpsReceiver::measure(const ReceiverPose& pose, const GpsSatelliteTruth& satellites) {
  step_clock();
  GpsReceiverEpoch& out = epoch_;
  out.receiver_clock_m = clock_m_;
  const Reception rx = reception(pose);
  out.apc_itrf_m = rx.r_apc;
  const std::size_t count = screen_visibility(rx, satellites);
  assign_channels(pose.t, count, satellites);

  out.measurement.t = pose.t;
  out.measurement.channel_count = 0;
  const auto channels = static_cast<std::size_t>(settings_.channels);
  for (std::size_t k = 0; k < channels; ++k) {
    Track& track = tracks_[k];
    if (track.prn == 0) continue;
    measure_channel(track, *candidate_of(track.prn, count, satellites), rx, pose.t, satellites);
  }
  return out;
}

// dt_r random walk: the first epoch keeps the initial offset drawn in create().
void GpsReceiver::step_clock() {
  if (!first_epoch_) clock_m_ += rng_.normal(settings_.clock_step_sigma_m);
  first_epoch_ = false;
}

// Antenna phase centre at the true reception time t_r = t - dt_r (the pose carried back along its
// Earth-fixed velocity), and the receiver's local axes for the ionosphere.
GpsReceiver::Reception GpsReceiver::reception(const ReceiverPose& pose) const {
  Reception rx;
  const double dt_receiver = clock_m_ / gnss::kGpsSpeedOfLight;
  rx.t_receive = pose.t - dt_receiver;
  const Eigen::Vector3d lever_itrf = pose.body_to_itrf * (phase_center_body_m() - pose.com_body_m);
  rx.r_apc = pose.com_itrf.r + lever_itrf - pose.com_itrf.v * dt_receiver;
  rx.v_apc = pose.com_itrf.v;
  rx.boresight = pose.body_to_itrf * boresight_body_;
  rx.where = core::geodetic_from_itrf(rx.r_apc);
  const double lat = rx.where.latitude;
  const double lon = rx.where.longitude;
  rx.east = Eigen::Vector3d(-std::sin(lon), std::cos(lon), 0.0);
  rx.north = Eigen::Vector3d(-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat));
  rx.up = Eigen::Vector3d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
  return rx;
}

// Visibility of every satellite (elevation above the antenna plane, ray clear of the Earth), at
// a typical light time; fills candidates_[0..count) in satellite order and epoch_.visible.
std::size_t GpsReceiver::screen_visibility(const Reception& rx, const GpsSatelliteTruth& satellites) {
  const std::size_t count = std::min(satellites.truth().size(), candidates_.size());
  epoch_.visible = 0;
  for (std::size_t j = 0; j < count; ++j) {
    Candidate& c = candidates_[j];
    c.index = j;
    const gnss::GpsSatelliteState s = satellites.true_state(j, rx.t_receive - 0.075);
    const Eigen::Vector3d to_satellite = s.r_ecef_m - rx.r_apc;
    const double distance = to_satellite.norm();
    const Eigen::Vector3d e = to_satellite / distance;
    c.elevation = std::asin(std::clamp(rx.boresight.dot(e), -1.0, 1.0));
    c.visible = c.elevation >= settings_.elevation_mask_rad &&
                grazing_height_m(rx.r_apc, e, distance) >= settings_.occultation_altitude_m;
    if (c.visible) ++epoch_.visible;
  }
  return count;
}

const GpsReceiver::Candidate* GpsReceiver::candidate_of(int prn, std::size_t count,
                                                        const GpsSatelliteTruth& satellites) const {
  for (std::size_t j = 0; j < count; ++j) {
    if (satellites.truth()[candidates_[j].index].prn == prn) return &candidates_[j];
  }
  return nullptr;
}

// Channels: keep visible tracks, free the others, then fill the free ones with the highest new
// satellites (a new track draws its ambiguity).
void GpsReceiver::assign_channels(core::GpsTime t, std::size_t count, const GpsSatelliteTruth& satellites) {
  const auto channels = static_cast<std::size_t>(settings_.channels);
  for (std::size_t k = 0; k < channels; ++k) {
    if (tracks_[k].prn == 0) continue;
    const Candidate* c = candidate_of(tracks_[k].prn, count, satellites);
    if (c == nullptr || !c->visible) tracks_[k].prn = 0;
  }
  std::sort(candidates_.begin(), candidates_.begin() + static_cast<std::ptrdiff_t>(count),
            [](const Candidate& a, const Candidate& b) {
              if (a.visible != b.visible) return a.visible;
              if (a.elevation != b.elevation) return a.elevation > b.elevation;
              return a.index < b.index;
            });
  for (std::size_t j = 0; j < count && candidates_[j].visible; ++j) {
    const int prn = satellites.truth()[candidates_[j].index].prn;
    bool tracked = false;
    for (std::size_t k = 0; k < channels; ++k) tracked = tracked || tracks_[k].prn == prn;
    if (tracked) continue;
    for (std::size_t k = 0; k < channels; ++k) {
      if (tracks_[k].prn != 0) continue;
      tracks_[k] = Track{prn, draw_ambiguity(), t};
      break;
    }
  }
}

// Loss of lock at this epoch: acquired now, or a cycle slip of +/- 1..max_slip_cycles (drawn
// with cycle_slip_probability), which restarts the lock time.
bool GpsReceiver::lost_lock(Track& track, core::GpsTime t) {
  if (track.lock_start == t) return true;  // acquired at this epoch
  if (!(settings_.cycle_slip_probability > 0.0 && rng_.uniform() < settings_.cycle_slip_probability)) return false;
  const auto size = 1 + static_cast<std::int64_t>(rng_.uniform() * settings_.max_slip_cycles);
  track.ambiguity += rng_.uniform() < 0.5 ? -size : size;
  track.lock_start = t;
  return true;
}

// Topside Klobuchar delay I along the unit line of sight e (zero when the ionosphere is off).
double GpsReceiver::ionosphere_m(const Reception& rx, const Eigen::Vector3d& e, core::GpsTime t) const {
  if (!settings_.ionosphere) return 0.0;
  const gnss::KlobucharGeometry g{rx.where.latitude, rx.where.longitude, std::atan2(e.dot(rx.east), e.dot(rx.north)),
                                  std::asin(std::clamp(e.dot(rx.up), -1.0, 1.0))};
  return gnss::klobuchar_topside_delay_m(settings_.klobuchar, g, rx.where.height, t, settings_.topside).value();
}

// P, Phi, D and C/N0 of one tracked satellite (the model in the header), appended to the epoch
// with the truth behind them.
void GpsReceiver::measure_channel(Track& track, const Candidate& c, const Reception& rx, core::GpsTime t,
                                  const GpsSatelliteTruth& satellites) {
  GpsReceiverEpoch& out = epoch_;
  const bool slipped = lost_lock(track, t);
  const SignalPath path = trace(satellites, c.index, rx.t_receive, rx.r_apc);
  const Eigen::Vector3d e = (path.r_satellite_m - rx.r_apc) / path.range_m;
  const double iono_m = ionosphere_m(rx, e, t);
  const double satellite_clock_m = gnss::kGpsSpeedOfLight * path.satellite.clock_bias_s;
  const double geometry_m = path.range_m + clock_m_ - satellite_clock_m;
  const double phase_offset = epoch_.receiver_phase_cycles - satellites.phase_offset_cycles(c.index);

  gnss::GpsChannelMeasurement& m = out.measurement.channels[static_cast<std::size_t>(out.measurement.channel_count)];
  m.prn = track.prn;
  m.pseudorange_m = geometry_m + iono_m + rng_.normal(settings_.code_sigma_m);
  m.carrier_phase_cycles = (geometry_m - iono_m + rng_.normal(settings_.phase_sigma_m)) / gnss::kL1WavelengthM +
                           static_cast<double>(track.ambiguity) + phase_offset;
  const double range_rate = e.dot(path.v_satellite_mps - rx.v_apc);
  m.doppler_hz = -(range_rate - gnss::kGpsSpeedOfLight * path.satellite.clock_drift_sps) / gnss::kL1WavelengthM +
                 rng_.normal(settings_.doppler_sigma_hz);
  m.cn0_dbhz = 35.0 + 15.0 * std::sin(std::max(c.elevation, 0.0));
  m.loss_of_lock = slipped;
  m.lock_time_s = t.seconds_since(track.lock_start);

  GpsChannelTruth& truth = out.truth[static_cast<std::size_t>(out.measurement.channel_count)];
  truth = GpsChannelTruth{track.prn, path.range_m, satellite_clock_m, iono_m, track.ambiguity,
                          satellites.phase_offset_cycles(c.index), c.elevation, e};
  ++out.measurement.channel_count;
}

}  // namespace visors::sim
