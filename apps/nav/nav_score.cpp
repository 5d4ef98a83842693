#include "apps/nav/nav_score.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "visors/core/rtn_frame.hpp"
#include "visors/nav/fix_truth.hpp"
#include "visors/nav/gps_measurement_model.hpp"
#include "visors/nav/gps_range_model.hpp"

namespace visors::nav_app {
namespace {

using nav::Craft;
using Json = nlohmann::json;

// A full fix against the truth's single differences of this epoch (nav/fix_truth.hpp).
bool wrong_fix(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& r,
               const std::map<int, std::pair<double, double>>& truth) {
  return nav::wrong_fix(filter, r, [&truth](int prn) {
    const auto it = truth.find(prn);
    return it == truth.end() ? NAN : it->second.second - it->second.first;
  });
}

// The covariance [m^2, GCRF] of the antennas' relative position, r_osc + C_osc p_osc - r_dsc -
// C_dsc p_dsc: J P J' (J over the scaled states).
Eigen::Matrix3d antenna_covariance(const nav::NavMatrix& P, const Eigen::Matrix3d& c_dsc, const Eigen::Matrix3d& c_osc) {
  Eigen::Matrix<double, 3, nav::kNavStates> J = Eigen::Matrix<double, 3, nav::kNavStates>::Zero();
  J.block<3, 3>(0, nav::state::position(Craft::kOsc)) = Eigen::Matrix3d::Identity();
  J.block<3, 3>(0, nav::state::position(Craft::kDsc)) = -Eigen::Matrix3d::Identity();
  J.block<3, 3>(0, nav::state::phase_center(Craft::kOsc)) = nav::state::kPhaseCenterUnit * c_osc;
  J.block<3, 3>(0, nav::state::phase_center(Craft::kDsc)) = -nav::state::kPhaseCenterUnit * c_dsc;
  return J * P * J.transpose();
}

// Where t_s lies against the run's observations: in a window, or in the slew to it or back from
// it (taken as long as the slew to it: the same angle at the same rate).
void locate(const RunInputs& in, double t_s, EpochScore& e) {
  for (const ObservationSpan& o : in.observations) {
    const double lead = o.start_s - o.slew_start_s;
    e.in_observation = e.in_observation || (t_s >= o.start_s && t_s <= o.end_s);
    e.in_slew = e.in_slew || (t_s >= o.slew_start_s && t_s < o.start_s) || (t_s > o.end_s && t_s <= o.end_s + lead);
  }
}

// The relative error of the payload reference points (the estimate's: its centres of mass and the
// nominal levers in the known attitudes; the truth's: the true centres of mass and levers in the
// true attitudes), split along the true line of sight OSC -> DSC and across it.
void score_payload(const std::array<core::StateVector, 2>& estimated_com, const std::array<CraftTruth, 2>& truth,
                   const std::array<Eigen::Quaterniond, 2>& known, const RunInputs& in, RelativeErrors& e) {
  const nav::LaserRangeGeometry told = laser_geometry(in.scenario.flight, known[0], known[1]);  // told levers, known attitudes
  const Eigen::Vector3d p_dsc = truth[0].x_gcrf.r + truth[0].body_to_gcrf * in.true_payload_lever_body_m[0];
  const Eigen::Vector3d p_osc = truth[1].x_gcrf.r + truth[1].body_to_gcrf * in.true_payload_lever_body_m[1];
  const Eigen::Vector3d est_dsc = estimated_com[0].r + told.dsc_body_to_gcrf * told.dsc_lever_body_m;
  const Eigen::Vector3d est_osc = estimated_com[1].r + told.osc_body_to_gcrf * told.osc_lever_body_m;
  const Eigen::Vector3d los = (p_dsc - p_osc).normalized();
  const Eigen::Vector3d error = (est_osc - est_dsc) - (p_osc - p_dsc);
  e.payload_los_m = -error.dot(los);  // > 0: the estimated OSC -> DSC distance is too long
  e.payload_lateral_m = (error - error.dot(los) * los).norm();
}

// Both spacecraft's estimated centres of mass and antennas (EpochScore), in the attitudes known
// at t_s (the ADCS's reports).
void estimate_states(const nav::NavVector& x, const RunInputs& in, double t_s, const std::array<Eigen::Quaterniond, 2>& known,
                     EpochScore& e) {
  for (const Craft craft : {Craft::kDsc, Craft::kOsc}) {
    const auto k = static_cast<std::size_t>(craft);
    e.com_gcrf[k] = nav::CdgpsFilter::centre_of_mass(x, craft);
    e.antenna_gcrf[k] = estimated_antenna(x, craft, in.scenario.flight, known[k], known_angular_velocity_gcrf(in, t_s, k));
  }
}

}  // namespace

core::StateVector estimated_antenna(const nav::NavVector& x, Craft craft, const sim::FlightKnowledge& told,
                                    const Eigen::Quaterniond& body_to_gcrf,
                                    const Eigen::Vector3d& omega_gcrf_radps) {
  const nav::ReceiverEstimate estimate = nav::receiver_estimate(x, craft);
  const Eigen::Vector3d lever_gcrf_m = nav::phase_centre_lever_gcrf_m(estimate, antenna_geometry(told, body_to_gcrf));
  return {estimate.r_gcrf_m + lever_gcrf_m, estimate.v_gcrf_mps + omega_gcrf_radps.cross(lever_gcrf_m)};
}

RelativeErrors relative_errors(const nav::NavVector& x, const RunInputs& in, double t_s) {
  RelativeErrors out;
  const auto truth = in.truth.find(key_ms(t_s));
  const auto* known = known_attitudes_at(in, t_s);
  if (truth == in.truth.end() || known == nullptr) return out;
  out.valid = true;
  const std::array<CraftTruth, 2>& true_crafts = truth->second;
  const core::StateVector& dsc = true_crafts[0].x_gcrf;
  const core::StateVector& osc = true_crafts[1].x_gcrf;
  const std::array<core::StateVector, 2> est = {nav::CdgpsFilter::centre_of_mass(x, Craft::kDsc),
                                                nav::CdgpsFilter::centre_of_mass(x, Craft::kOsc)};
  out.gcrf_to_rtn = core::gcrf_to_rtn_matrix(dsc);
  out.position_rtn_m = out.gcrf_to_rtn * ((est[1].r - est[0].r) - (osc.r - dsc.r));
  out.velocity_rtn_mps = out.gcrf_to_rtn * ((est[1].v - est[0].v) - (osc.v - dsc.v));
  score_payload(est, true_crafts, *known, in, out);
  // Antenna error: the estimate's antenna, CoM + C_known (known lever + p) (estimated_antenna),
  // minus the truth's, CoM_true + C_true (true lever); the two attitudes differ by the ADCS's
  // determination error.
  out.c_dsc = (*known)[0].toRotationMatrix();
  out.c_osc = (*known)[1].toRotationMatrix();
  const auto antenna_error = [&](Craft craft, std::size_t k) {
    const Eigen::Vector3d estimated = estimated_antenna(x, craft, in.scenario.flight, (*known)[k], Eigen::Vector3d::Zero()).r;
    return Eigen::Vector3d(estimated - (true_crafts[k].x_gcrf.r + true_crafts[k].body_to_gcrf * in.true_antenna_lever_body_m[k]));
  };
  out.antenna_rtn_m = out.gcrf_to_rtn * (antenna_error(Craft::kOsc, 1) - antenna_error(Craft::kDsc, 0));
  return out;
}

EpochScore score(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& r, const RunInputs& in, double t_s,
                 Craft local) {
  EpochScore e;
  e.t_s = t_s;
  locate(in, t_s, e);
  const bool full = r.fix_applied && r.fix.outcome == nav::FixOutcome::kFixed;
  e.status = full ? "fixed" : r.fix_applied ? "partial" : "float";
  const nav::NavVector& x = r.fix_applied ? filter.x_fixed() : filter.x();
  const RelativeErrors relative = relative_errors(x, in, t_s);
  if (!relative.valid) return e;
  e.relative_position_rtn_m = relative.position_rtn_m;
  e.relative_velocity_rtn_mps = relative.velocity_rtn_mps;
  e.relative_antenna_rtn_m = relative.antenna_rtn_m;
  e.payload_los_m = relative.payload_los_m;
  e.payload_lateral_m = relative.payload_lateral_m;
  e.forecast_antenna_rtn_m = relative.antenna_rtn_m;  // no delay: the epoch's own
  e.forecast_velocity_rtn_mps = relative.velocity_rtn_mps;
  // Normalised estimation error squared of the antennas' relative position, and its 1-sigma per RTN axis.
  const Eigen::Matrix3d S_rtn = relative.gcrf_to_rtn *
                                antenna_covariance(r.fix_applied ? filter.P_fixed() : filter.P(), relative.c_dsc, relative.c_osc) *
                                relative.gcrf_to_rtn.transpose();
  e.nees = e.relative_antenna_rtn_m.dot(S_rtn.ldlt().solve(e.relative_antenna_rtn_m));
  e.antenna_sigma_rtn_m = S_rtn.diagonal().cwiseSqrt();
  const std::array<CraftTruth, 2>& truth = in.truth.find(key_ms(t_s))->second;
  estimate_states(x, in, t_s, *known_attitudes_at(in, t_s), e);  // relative.valid: both are at t_s
  const std::size_t own = local == Craft::kDsc ? 0 : 1;
  const core::StateVector estimate = nav::CdgpsFilter::centre_of_mass(x, local);
  e.absolute_position_m = (estimate.r - truth[own].x_gcrf.r).norm();
  e.absolute_velocity_mps = (estimate.v - truth[own].x_gcrf.v).norm();
  e.clock_error_dsc_m = x(nav::state::clock(Craft::kDsc)) - truth[0].receiver_clock_m;
  e.clock_error_osc_m = x(nav::state::clock(Craft::kOsc)) - truth[1].receiver_clock_m;
  if (full) {
    const auto phases = in.phase_truth.find(key_ms(t_s));
    e.wrong_fix = phases != in.phase_truth.end() && wrong_fix(filter, r, phases->second);
  }
  e.empirical_dsc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kDsc));
  e.empirical_osc_rtn_mps2 = nav::state::kEmpiricalUnit * x.segment<3>(nav::state::empirical_acceleration(Craft::kOsc));
  e.double_differences = r.double_differences;
  e.satellites = r.sdcp_used;
  e.graphic_used = r.graphic_used;
  e.graphic_rejected = r.graphic_rejected;
  e.sdcp_rejected = r.sdcp_rejected;
  e.nis_sum = r.nis_sum;
  e.nis_count = r.nis_count;
  e.graphic_nis_sum = r.graphic_nis_sum;
  e.sdcp_nis_sum = r.sdcp_nis_sum;
  e.sdcp_used = r.sdcp_used;
  e.detected_slips = r.detected_slips;
  e.ephemeris_switches = r.ephemeris_switches;
  return e;
}

namespace {

double rms(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x * x;
  return v.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(v.size()));
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(p * static_cast<double>(v.size())))];
}

// Error statistics over a window of epochs.
struct WindowStats {
  std::vector<double> rel_pos, rel_antenna, rel_vel, abs_pos, abs_vel, forecast_antenna, forecast_vel;
  double nees_sum = 0.0;
  double worst = 0.0, worst_antenna = 0.0;
  double worst_outside_slews = 0.0, worst_antenna_outside_slews = 0.0;
  int fixed = 0, partial = 0, wrong = 0;
  std::size_t time_tags = 0;  // the receiver's time tags in the window, recorded or not

  void add(const EpochScore& e) {
    rel_pos.push_back(e.relative_position_rtn_m.norm());
    rel_antenna.push_back(e.relative_antenna_rtn_m.norm());
    rel_vel.push_back(e.relative_velocity_rtn_mps.norm());
    forecast_antenna.push_back(e.forecast_antenna_rtn_m.norm());
    forecast_vel.push_back(e.forecast_velocity_rtn_mps.norm());
    abs_pos.push_back(e.absolute_position_m);
    abs_vel.push_back(e.absolute_velocity_mps);
    worst = std::max(worst, e.relative_position_rtn_m.norm());
    worst_antenna = std::max(worst_antenna, e.relative_antenna_rtn_m.norm());
    if (!e.in_slew) {
      worst_outside_slews = std::max(worst_outside_slews, e.relative_position_rtn_m.norm());
      worst_antenna_outside_slews = std::max(worst_antenna_outside_slews, e.relative_antenna_rtn_m.norm());
    }
    fixed += std::string_view(e.status) == "fixed" ? 1 : 0;
    partial += std::string_view(e.status) == "partial" ? 1 : 0;
    wrong += e.wrong_fix ? 1 : 0;
    nees_sum += e.nees;
  }

  [[nodiscard]] Json json() const {
    const double n = static_cast<double>(rel_pos.size());
    return Json{{"epochs", rel_pos.size()},
                {"fix_rate", n > 0 ? fixed / n : 0.0},
                {"time_tags", time_tags},
                {"fix_rate_all_epochs", time_tags > 0 ? fixed / static_cast<double>(time_tags) : 0.0},
                {"partial_rate", n > 0 ? partial / n : 0.0},
                {"wrong_fix_epochs", wrong},
                {"relative_position_rms_m", rms(rel_pos)},
                {"relative_position_worst_m", worst},
                {"relative_antenna_rms_m", rms(rel_antenna)},
                {"relative_antenna_worst_m", worst_antenna},
                {"relative_position_worst_outside_slews_m", worst_outside_slews},
                {"relative_antenna_worst_outside_slews_m", worst_antenna_outside_slews},
                {"relative_velocity_rms_mps", rms(rel_vel)},
                {"absolute_position_rms_m", rms(abs_pos)},
                {"absolute_velocity_rms_mps", rms(abs_vel)},
                {"antenna_nees_mean", n > 0 ? nees_sum / n : 0.0},
                {"forecast_antenna_rms_m", rms(forecast_antenna)},
                {"forecast_antenna_worst_m", forecast_antenna.empty() ? 0.0 : *std::max_element(forecast_antenna.begin(), forecast_antenna.end())},
                {"forecast_velocity_rms_mps", rms(forecast_vel)}};
  }
};

// The payload points' relative error during the observations, and the laser ranges.
struct ObservationStats {
  std::vector<double> los, lateral;
  int laser_used = 0, laser_rejected = 0;

  void add(const EpochScore& e) {
    const std::string_view laser(e.laser);
    laser_used += laser == "used" ? 1 : 0;
    laser_rejected += laser == "rejected" ? 1 : 0;
    if (!e.in_observation) return;
    los.push_back(e.payload_los_m);
    lateral.push_back(e.payload_lateral_m);
  }

  [[nodiscard]] Json json() const {
    return Json{{"epochs", los.size()},
                {"payload_los_rms_m", rms(los)},
                {"payload_los_worst_m", los.empty() ? 0.0 : std::abs(*std::max_element(los.begin(), los.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }))},
                {"payload_lateral_rms_m", rms(lateral)},
                {"laser_ranges_used", laser_used},
                {"laser_ranges_rejected", laser_rejected}};
  }
};

constexpr double kConvergenceS = 300.0;  // the "converged" window starts this long after the first fix [s]

// The receiver's time tags from from_s after the cold start on, as the windows take their epochs
// (the cold start's own epoch, which the filter starts from, excluded), whether the receiver
// recorded them or not. 1 us of slack: the tags are truth.csv's, the epochs' times the RINEX's.
std::size_t count_time_tags(const Replay& r, double from_s) {
  if (r.start_s < 0.0) return 0;
  constexpr double kSlackS = 1e-6;
  return static_cast<std::size_t>(std::count_if(r.time_tags_s.begin(), r.time_tags_s.end(), [&](double t_s) {
    return t_s > r.start_s + kSlackS && t_s - r.start_s >= from_s - kSlackS;
  }));
}

}  // namespace

// The replay's acceptance figures over the epochs after the first fix, and over those from
// kConvergenceS later (the velocity takes minutes to converge after a cold start). A replay that
// never fixes (--float, or no fix possible) is scored from its cold start instead.
Json summarise(const Replay& r) {
  const double window_start_s = std::max(0.0, r.first_fix_s);  // after the cold start [s]
  WindowStats after_fix, converged;
  ObservationStats observations;
  std::vector<double> steps;
  int slips = 0, switches = 0, nis_count = 0, wrong_run = 0, longest_wrong_run = 0;
  double nis = 0.0, outage_end_s = -1.0, refix_s = -1.0;
  for (const EpochScore& e : r.epochs) {
    if (std::string_view(e.status) == "outage") outage_end_s = e.t_s + 1.0;
    if (outage_end_s >= 0.0 && refix_s < 0.0 && std::string_view(e.status) == "fixed") refix_s = e.t_s - outage_end_s;
    wrong_run = e.wrong_fix ? wrong_run + 1 : 0;
    longest_wrong_run = std::max(longest_wrong_run, wrong_run);
    steps.push_back(e.step_us);
    slips += e.detected_slips;
    switches += e.ephemeris_switches;
    nis += e.nis_sum;
    nis_count += e.nis_count;
    observations.add(e);
    if (r.start_s < 0.0 || e.t_s - r.start_s < window_start_s) continue;
    after_fix.add(e);
    if (e.t_s - r.start_s >= window_start_s + kConvergenceS) converged.add(e);
  }
  after_fix.time_tags = count_time_tags(r, window_start_s);
  converged.time_tags = count_time_tags(r, window_start_s + kConvergenceS);
  return Json{{"filter", r.name},
              {"epochs", r.epochs.size()},
              {"start_s", r.start_s},
              {"time_to_first_fix_s", r.first_fix_s},
              {"latency_s", r.latency_s},
              {"window_from", r.first_fix_s >= 0.0 ? "first_fix" : "cold_start"},
              {"after_first_fix", after_fix.json()},
              {"converged", converged.json()},
              {"observations", observations.json()},
              {"impulses_applied", r.impulse_t_s.size()},
              {"detected_slips", slips},
              {"ephemeris_switches", switches},
              {"longest_wrong_fix_s", longest_wrong_run},
              {"refix_after_outage_s", refix_s},
              {"nis_mean", nis_count > 0 ? nis / nis_count : 0.0},
              {"step_us", {{"median", percentile(steps, 0.5)}, {"p99_9", percentile(steps, 0.999)}}}};
}

}  // namespace visors::nav_app
