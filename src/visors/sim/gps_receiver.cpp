#include "visors/sim/gps_receiver.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "visors/core/geodetic.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::sim {

core::Result<bool> GpsReceiverSettings::validate() const {
  const struct {
    const char* name;
    double value;
  } non_negative[] = {{"code_sigma_m", code_sigma_m},
                      {"phase_sigma_m", phase_sigma_m},
                      {"doppler_sigma_hz", doppler_sigma_hz},
                      {"clock_step_sigma_m", clock_step_sigma_m},
                      {"epoch_interval_s", epoch_interval_s},
                      {"initial_clock_sigma_m", initial_clock_sigma_m},
                      {"phase_center_offset_m", phase_center_offset_m},
                      {"mounting_sigma_rad", mounting_sigma_rad},
                      {"occultation_altitude_m", occultation_altitude_m},
                      {"half_cycle_resolve_s", half_cycle_resolve_s},
                      {"code_multipath_m", code_multipath_m},
                      {"phase_multipath_m", phase_multipath_m},
                      {"data_gap_s", data_gap_s}};
  for (const auto& f : non_negative) {
    if (!(std::isfinite(f.value) && f.value >= 0.0)) return core::Error{f.name, "must be finite and >= 0"};
  }
  if (!(epoch_interval_s > 0.0)) return core::Error{"epoch_interval_s", "must be > 0"};
  if (!(std::abs(elevation_mask_rad) < 0.5 * core::kPi)) return core::Error{"elevation_mask_rad", "must be in (-pi/2, pi/2)"};
  if (channels < 1 || channels > gnss::kMaxGpsChannels) return core::Error{"channels", "must be in 1..12"};
  if (!(cycle_slip_probability >= 0.0 && cycle_slip_probability <= 1.0)) {
    return core::Error{"cycle_slip_probability", "must be in [0, 1]"};
  }
  if (max_slip_cycles < 1) return core::Error{"max_slip_cycles", "must be >= 1"};
  const struct {
    const char* name;
    double value;
  } probabilities[] = {{"unflagged_slip_fraction", unflagged_slip_fraction},
                       {"half_cycle_slip_probability", half_cycle_slip_probability},
                       {"data_gap_probability", data_gap_probability}};
  for (const auto& f : probabilities) {
    if (!(f.value >= 0.0 && f.value <= 1.0)) return core::Error{f.name, "must be in [0, 1]"};
  }
  if (!(std::isfinite(multipath_tau_s) && multipath_tau_s > 0.0)) return core::Error{"multipath_tau_s", "must be finite and > 0"};
  if (!antenna_body_m.allFinite()) return core::Error{"antenna_body_m", "must be finite"};
  if (!phase_center_error_body_m.allFinite()) return core::Error{"phase_center_error_body_m", "must be finite"};
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

constexpr double kIonosphereRateStep = 0.1;
constexpr double kNoiseFloorElevation = 5.0 * core::kDegToRad;  // the 1/sin(el) scale is capped here
constexpr double kLongGapS = 30.0;  // a longer data gap makes every channel re-acquire

// 1 / sin(elevation above the antenna plane), the elevation floored at 5 deg.
double elevation_scale(double elevation_rad) { return 1.0 / std::sin(std::max(elevation_rad, kNoiseFloorElevation)); }  // half-width of the ionosphere rate's central difference [s]

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
  receiver.clock_rate_mps_ = receiver.rng_.normal(settings.clock_step_sigma_m) / settings.epoch_interval_s;  // f_-1
  receiver.prn_rng_.reserve(gnss::kMaxGpsPrn + 1);
  for (int prn = 0; prn <= gnss::kMaxGpsPrn; ++prn) {
    const auto seed = static_cast<std::uint64_t>(receiver.rng_.uniform() * 9007199254740992.0);  // 53 random bits
    receiver.prn_rng_.emplace_back(seed, "gps.prn");
  }
  return receiver;
}

void GpsReceiver::reacquire_all() {
  for (Track& track : tracks_) track.prn = 0;
}

std::int64_t GpsReceiver::draw_ambiguity(int prn) {
  // An arbitrary integer in [-2^20, 2^20): a receiver starts the phase count anywhere.
  return static_cast<std::int64_t>(std::floor(prn_rng(prn).uniform() * 2097152.0)) - 1048576;
}

// A geodetic position and its local axes (the Klobuchar model's azimuth and elevation are
// measured in them).
struct GpsReceiver::LocalAxes {
  core::GeodeticPosition where;
  Eigen::Vector3d east, north, up;

  static LocalAxes at(const Eigen::Vector3d& r_itrf) {
    LocalAxes a;
    a.where = core::geodetic_from_itrf(r_itrf);
    const double lat = a.where.latitude;
    const double lon = a.where.longitude;
    a.east = Eigen::Vector3d(-std::sin(lon), std::cos(lon), 0.0);
    a.north = Eigen::Vector3d(-std::sin(lat) * std::cos(lon), -std::sin(lat) * std::sin(lon), std::cos(lat));
    a.up = Eigen::Vector3d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon), std::sin(lat));
    return a;
  }
};

// The antenna at the true reception time t_r = t - dt_r, with its local axes, and (ionosphere on)
// the local axes kIonosphereRateStep before and after along its velocity.
struct GpsReceiver::Reception {
  core::GpsTime t_receive;
  Eigen::Vector3d r_apc;      // phase centre, Earth-fixed [m]
  Eigen::Vector3d v_apc;      // its Earth-fixed velocity [m/s]
  Eigen::Vector3d boresight;  // true boresight, Earth-fixed (unit)
  LocalAxes here, before, after;
};

const GpsReceiverEpoch& GpsReceiver::measure(const ReceiverPose& pose, const GpsSatelliteTruth& satellites) {
  step_clock(pose.t);
  step_gap(pose.t);
  GpsReceiverEpoch& out = epoch_;
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

// Data gaps: outside a gap, one starts at this epoch with data_gap_probability (no draw when 0);
// at the first epoch after a gap longer than 30 s every channel is freed (re-acquired below).
void GpsReceiver::step_gap(core::GpsTime t) {
  if (gap_active_ && t.seconds_since(gap_until_) >= -1e-9) {
    gap_active_ = false;
    if (reacquire_after_gap_) {
      for (Track& track : tracks_) track.prn = 0;
      reacquire_after_gap_ = false;
    }
  }
  if (!gap_active_ && settings_.data_gap_probability > 0.0 && rng_.uniform() < settings_.data_gap_probability) {
    gap_active_ = true;
    gap_until_ = t + settings_.data_gap_s;
    reacquire_after_gap_ = settings_.data_gap_s > kLongGapS;
    if (!(settings_.data_gap_s > 0.0)) gap_active_ = false;
  }
  epoch_.recorded = !gap_active_;
}

// The clock at t along its current slope (the first epoch keeps the offset drawn in create()),
// the slope from t on drawn, and the rate at t: the mean of the slopes before and after.
void GpsReceiver::step_clock(core::GpsTime t) {
  if (!first_epoch_) clock_m_ += clock_rate_mps_ * t.seconds_since(last_epoch_);
  const double slope_before = clock_rate_mps_;
  clock_rate_mps_ = rng_.normal(settings_.clock_step_sigma_m) / settings_.epoch_interval_s;
  last_epoch_ = t;
  first_epoch_ = false;
  epoch_.receiver_clock_m = clock_m_;
  epoch_.receiver_clock_rate_mps = 0.5 * (slope_before + clock_rate_mps_);
}

// Antenna phase centre at the true reception time t_r = t - dt_r (the pose carried back along the
// phase centre's Earth-fixed velocity: the centre of mass's plus the attitude rotation's), and the
// receiver's local axes for the ionosphere.
GpsReceiver::Reception GpsReceiver::reception(const ReceiverPose& pose) const {
  Reception rx;
  const double dt_receiver = clock_m_ / gnss::kGpsSpeedOfLight;
  rx.t_receive = pose.t - dt_receiver;
  const Eigen::Vector3d lever_itrf = pose.body_to_itrf * (phase_center_body_m() - pose.com_body_m);
  rx.v_apc = pose.com_itrf.v + pose.angular_velocity_itrf.cross(lever_itrf);
  rx.r_apc = pose.com_itrf.r + lever_itrf - rx.v_apc * dt_receiver;
  rx.boresight = pose.body_to_itrf * boresight_body_;
  rx.here = LocalAxes::at(rx.r_apc);
  if (settings_.ionosphere) {
    rx.before = LocalAxes::at(rx.r_apc - kIonosphereRateStep * rx.v_apc);
    rx.after = LocalAxes::at(rx.r_apc + kIonosphereRateStep * rx.v_apc);
  }
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
    const Eigen::Vector3d to_satellite = satellites.screening_position_ecef(j, rx.t_receive - 0.075) - rx.r_apc;
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
      tracks_[k] = Track{};
      tracks_[k].prn = prn;
      tracks_[k].ambiguity = draw_ambiguity(prn);
      tracks_[k].lock_start = t;
      tracks_[k].acquired = t;
      break;
    }
  }
}

// A new ambiguity at this epoch (returned; `flagged`: with LLI bit 0): acquired now (then a
// half cycle with half_cycle_slip_probability), the half cycle resolved (the phase jumps), or a
// cycle slip of +/- 1..max_slip_cycles (drawn with cycle_slip_probability), which restarts the
// lock time unless it is one of the unflagged_slip_fraction the receiver does not notice.
bool GpsReceiver::lost_lock(Track& track, core::GpsTime t, bool& flagged) {
  flagged = true;
  if (track.lock_start == t) {  // acquired at this epoch
    track.half_cycle =
        settings_.half_cycle_slip_probability > 0.0 && prn_rng(track.prn).uniform() < settings_.half_cycle_slip_probability;
    return true;
  }
  if (track.half_cycle && t.seconds_since(track.acquired) >= settings_.half_cycle_resolve_s - 1e-9) {
    track.half_cycle = false;
    track.lock_start = t;
    return true;
  }
  RandomStream& rng = prn_rng(track.prn);
  if (!(settings_.cycle_slip_probability > 0.0 && rng.uniform() < settings_.cycle_slip_probability)) return false;
  const auto size = 1 + static_cast<std::int64_t>(rng.uniform() * settings_.max_slip_cycles);
  track.ambiguity += rng.uniform() < 0.5 ? -size : size;
  flagged = !(settings_.unflagged_slip_fraction > 0.0 && rng.uniform() < settings_.unflagged_slip_fraction);
  if (flagged) track.lock_start = t;
  return true;
}

// The channel's Gauss-Markov multipath states at t: drawn N(0, sigma) at acquisition, then
// x <- a x + sqrt(1 - a^2) sigma w, a = exp(-dt / tau) (no draw for a zero sigma).
void GpsReceiver::step_multipath(Track& track, core::GpsTime t) {
  const double sc = settings_.code_multipath_m, sp = settings_.phase_multipath_m;
  if (!(sc > 0.0 || sp > 0.0)) return;
  RandomStream& rng = prn_rng(track.prn);
  if (track.acquired == t) {
    if (sc > 0.0) track.code_multipath = rng.normal(sc);
    if (sp > 0.0) track.phase_multipath = rng.normal(sp);
  } else {
    const double a = std::exp(-t.seconds_since(track.multipath_time) / settings_.multipath_tau_s);
    const double b = std::sqrt(std::max(0.0, 1.0 - a * a));
    if (sc > 0.0) track.code_multipath = a * track.code_multipath + b * rng.normal(sc);
    if (sp > 0.0) track.phase_multipath = a * track.phase_multipath + b * rng.normal(sp);
  }
  track.multipath_time = t;
}

// Topside Klobuchar delay I at `at` along the unit line of sight e (zero when the ionosphere is off).
double GpsReceiver::ionosphere_m(const LocalAxes& at, const Eigen::Vector3d& e, core::GpsTime t) const {
  if (!settings_.ionosphere) return 0.0;
  const gnss::KlobucharGeometry g{at.where.latitude, at.where.longitude, std::atan2(e.dot(at.east), e.dot(at.north)),
                                  std::asin(std::clamp(e.dot(at.up), -1.0, 1.0))};
  return gnss::klobuchar_topside_delay_m(settings_.klobuchar, g, at.where.height, t, settings_.topside).value();
}

// dI/dt: the central difference over +/- kIonosphereRateStep, the receiver and the satellite
// (Earth-fixed position and velocity in the reception-time axes) moved along their velocities
// and the time tag with them (zero when the ionosphere is off).
double GpsReceiver::ionosphere_rate_mps(const Reception& rx, const Eigen::Vector3d& r_satellite,
                                        const Eigen::Vector3d& v_satellite, core::GpsTime t) const {
  if (!settings_.ionosphere) return 0.0;
  const double h = kIonosphereRateStep;
  const Eigen::Vector3d e_before = (r_satellite - rx.r_apc - h * (v_satellite - rx.v_apc)).normalized();
  const Eigen::Vector3d e_after = (r_satellite - rx.r_apc + h * (v_satellite - rx.v_apc)).normalized();
  return (ionosphere_m(rx.after, e_after, t + h) - ionosphere_m(rx.before, e_before, t - h)) / (2.0 * h);
}

// P, Phi, D and C/N0 of one tracked satellite (the model in the header), appended to the epoch
// with the truth behind them.
void GpsReceiver::measure_channel(Track& track, const Candidate& candidate, const Reception& rx, core::GpsTime t,
                                  const GpsSatelliteTruth& satellites) {
  GpsReceiverEpoch& out = epoch_;
  bool flagged = false;
  const bool slipped = lost_lock(track, t, flagged);
  const SignalPath path = trace(satellites, candidate.index, rx.t_receive, rx.r_apc);
  const Eigen::Vector3d e = (path.r_satellite_m - rx.r_apc) / path.range_m;
  const double iono_m = ionosphere_m(rx.here, e, t);
  const double satellite_clock_m = gnss::kGpsSpeedOfLight * path.satellite.clock_bias_s;
  // Rates with respect to the time tag (header): d rho/dt_r of the light-time solution, the
  // satellite clock at t_r - tau, both times dt_r/dt; the receiver clock's; the ionosphere's.
  const double c = gnss::kGpsSpeedOfLight;
  const Eigen::Vector3d v_satellite_inertial =
      path.v_satellite_mps + gnss::kGpsEarthRate * Eigen::Vector3d::UnitZ().cross(path.r_satellite_m);
  const double range_rate_receive = e.dot(path.v_satellite_mps - rx.v_apc) / (1.0 + e.dot(v_satellite_inertial) / c);
  const double receive_per_tag = 1.0 - out.receiver_clock_rate_mps / c;
  const double range_rate = range_rate_receive * receive_per_tag;
  const double satellite_clock_rate =
      c * path.satellite.clock_drift_sps * (1.0 - range_rate_receive / c) * receive_per_tag;
  const double iono_rate = ionosphere_rate_mps(rx, path.r_satellite_m, path.v_satellite_mps, t);
  const double geometry_m = path.range_m + clock_m_ - satellite_clock_m;
  const double phase_offset = epoch_.receiver_phase_cycles - satellites.phase_offset_cycles(candidate.index);

  gnss::GpsChannelMeasurement& m = out.measurement.channels[static_cast<std::size_t>(out.measurement.channel_count)];
  m.prn = track.prn;
  const double scale = elevation_scale(candidate.elevation);
  const double noise_scale = settings_.elevation_dependent_noise ? scale : 1.0;
  RandomStream& rng = prn_rng(track.prn);
  m.pseudorange_m = geometry_m + iono_m + rng.normal(noise_scale * settings_.code_sigma_m);
  m.carrier_phase_cycles = (geometry_m - iono_m + rng.normal(noise_scale * settings_.phase_sigma_m)) / gnss::kL1WavelengthM +
                           static_cast<double>(track.ambiguity) + phase_offset;
  m.doppler_hz = -(range_rate + out.receiver_clock_rate_mps - satellite_clock_rate - iono_rate) / gnss::kL1WavelengthM +
                 rng.normal(settings_.doppler_sigma_hz);
  m.cn0_dbhz = settings_.elevation_dependent_noise ? 50.0 - 20.0 * std::log10(scale)
                                                   : 35.0 + 15.0 * std::sin(std::max(candidate.elevation, 0.0));
  step_multipath(track, t);
  const double code_multipath = scale * track.code_multipath;
  const double phase_multipath = scale * track.phase_multipath;
  if (settings_.code_multipath_m > 0.0) m.pseudorange_m += code_multipath;
  if (settings_.phase_multipath_m > 0.0) m.carrier_phase_cycles += phase_multipath / gnss::kL1WavelengthM;
  if (track.half_cycle) m.carrier_phase_cycles += 0.5;
  m.loss_of_lock = (slipped && flagged) || track.pending_lli;
  m.half_cycle_ambiguity = track.half_cycle;
  track.pending_lli = out.recorded ? false : m.loss_of_lock;
  m.lock_time_s = t.seconds_since(track.lock_start);

  GpsChannelTruth& truth = out.truth[static_cast<std::size_t>(out.measurement.channel_count)];
  truth = GpsChannelTruth{track.prn, path.range_m, satellite_clock_m, iono_m, track.ambiguity,
                          satellites.phase_offset_cycles(candidate.index), candidate.elevation, e,
                          range_rate, satellite_clock_rate, iono_rate, track.half_cycle ? 0.5 : 0.0, slipped,
                          code_multipath, phase_multipath};
  ++out.measurement.channel_count;
}

}  // namespace visors::sim
