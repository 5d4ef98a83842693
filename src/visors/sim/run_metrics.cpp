#include "visors/sim/run_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "visors/astro/apparent_sun.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/sim/host_application.hpp"
#include "visors/sim/navigation_setup.hpp"
#include "visors/sim/sensors.hpp"

namespace visors::sim {
namespace {

// Truth relative geometry (every step: the minimum separations): RTN position and inertial
// velocity difference in RTN axes, RN and 3D separations.
TimeseriesRow truth_geometry(const core::StateVector& dsc, const core::StateVector& osc) {
  TimeseriesRow row;
  const Eigen::Matrix3d to_rtn = core::gcrf_to_rtn_matrix(dsc);
  row.r_rtn_m = to_rtn * (osc.r - dsc.r);
  row.v_rtn_mps = to_rtn * (osc.v - dsc.v);
  row.sep_3d_m = row.r_rtn_m.norm();
  row.sep_rn_m = std::hypot(row.r_rtn_m(0), row.r_rtn_m(2));
  return row;
}

// Truth ROE for the time series (output steps only: the mean elements are iterated): osculating,
// and mean through the first-order J2 mean elements of both spacecraft.
void add_truth_roe(const core::StateVector& dsc, const core::StateVector& osc, const core::EarthGravityConstants& g,
                   TimeseriesRow& row) {
  const auto kc = astro::cartesian_to_keplerian(dsc.r, dsc.v, g.mu);
  const auto kd = astro::cartesian_to_keplerian(osc.r, osc.v, g.mu);
  if (!kc.ok() || !kd.ok()) return;
  if (const auto roe = astro::roe_from_keplerian(*kc, *kd); roe.ok()) row.roe_osc_m = kc->a * *roe;
  const auto mc = astro::mean_from_osculating(*kc, g);
  const auto md = astro::mean_from_osculating(*kd, g);
  if (!mc.ok() || !md.ok()) return;
  if (const auto roe = astro::roe_from_keplerian(*mc, *md); roe.ok()) row.roe_mean_m = mc->a * *roe;
}

// The angle between the true payload line of sight and the target's apparent direction [rad].
double payload_pointing_rad(const TruthSpacecraft& x) {
  const Eigen::Vector3d los_gcrf = x.q_body_to_gcrf * x.geometry->payload_axis_body();
  return std::atan2(los_gcrf.cross(x.target_unit_gcrf).norm(), los_gcrf.dot(x.target_unit_gcrf));
}

// The true drag acceleration, OSC minus DSC, in the DSC's RTN axes [m/s^2].
Eigen::Vector3d drag_difference_rtn(const TruthWorld& truth, core::GpsTime t) {
  return core::gcrf_to_rtn_matrix(truth[0].x_gcrf) * (truth.drag_acceleration_gcrf(1, t) - truth.drag_acceleration_gcrf(0, t));
}

// The osculating orbit's angular rate |r x v| / r^2, the HCW mean motion [rad/s].
double mean_motion_radps(const core::StateVector& x) { return x.r.cross(x.v).norm() / x.r.squaredNorm(); }

// The true differential drag along the DSC's T axis (the quantity the flight software's estimator
// measures, differential_drag_estimator.hpp) and the active spacecraft's estimate of it.
void add_drag(const TruthWorld& truth, core::GpsTime t, const gnc::Telemetry& active, TimeseriesRow& row) {
  for (std::size_t k = 0; k < 2; ++k) row.drag_area_m2[k] = truth.drag_area_m2(k);
  row.drag_t_difference_mps2 = drag_difference_rtn(truth, t)(1);
  row.has_drag_estimate = active.drag_valid;
  row.drag_t_estimate_mps2 = active.differential_drag_mps2;
}

}  // namespace

RunMetrics::RunMetrics(RunRecorder& recorder, int observations, double step_s) : recorder_(&recorder), step_s_(step_s) {
  observations_.reserve(static_cast<std::size_t>(std::max(observations, 0)) + 4);
}

void RunMetrics::open_observation(int index, double start_s, double end_s) {
  PendingObservation p;
  p.result.index = index;
  p.result.t_s = start_s;
  p.start_s = start_s;
  p.end_s = end_s;
  observations_.push_back(p);
}

void RunMetrics::add_delta_v(std::size_t k, gnc::Mode mode, double l1_mps) {
  dv_by_mode_mps_[k][static_cast<std::size_t>(mode)] += l1_mps;
  dv_total_mps_[k] += l1_mps;
}

void RunMetrics::score_navigation(const TruthWorld& truth, const Sensors& sensors, const HostApplication& host,
                                  const FlightKnowledge& told, double t_s, bool in_slew) {
  FormationTruth formation;
  formation.dsc_gcrf = truth[0].x_gcrf;
  formation.osc_gcrf = truth[1].x_gcrf;
  formation.dsc_body_to_gcrf = truth[0].q_body_to_gcrf.toRotationMatrix();
  formation.osc_body_to_gcrf = truth[1].q_body_to_gcrf.toRotationMatrix();
  // True minus known lever arm from the centre of mass to the phase centre: the known one is the
  // flight software's, the true one the receiver's (drawn centre of mass, tilted boresight,
  // phase-centre error).
  const Eigen::Vector3d known = known_antenna_lever_body_m(told);
  const auto lever_error = [&](std::size_t k) -> Eigen::Vector3d {
    return (sensors.receiver(k).phase_center_body_m() - truth[k].geometry->com_body_m()) - known;
  };
  formation.dsc_lever_error_m = lever_error(0);
  formation.osc_lever_error_m = lever_error(1);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::optional<gnc::NavigationTelemetry>& record = host[k].out.navigation;  // its last step's
    if (!record) continue;
    navigation_samples_[k] = navigation_score_.score(host[k].id, *record, t_s, formation, in_slew);
  }
}

void RunMetrics::set_aim(core::GpsTime t0, const control::ScienceGeometry& geometry) {
  aim_t0_ = t0;
  aim_geometry_ = geometry;
}

void RunMetrics::add_impulse_error(std::size_t k, double t_s, const Eigen::Vector3d& dv_error_gcrf_mps,
                                   const core::StateVector& dsc_gcrf) {
  const double sign = k == 1 ? 1.0 : -1.0;  // relative: OSC minus DSC
  last_burn_ = LastBurn{t_s, sign * (core::gcrf_to_rtn_matrix(dsc_gcrf) * dv_error_gcrf_mps),
                        mean_motion_radps(dsc_gcrf)};
  drag_since_burn_.clear();
}

// The drag prediction's impulses are kept from this long before a pending observation's start
// (the fine-control window, 900 s by default, holds the last burn) [s].
constexpr double kDragLookback_s = 1200.0;

void RunMetrics::record_drag_prediction(const TruthWorld& truth, const HostApplication& host, core::GpsTime t,
                                        double t_s) {
  const bool near = std::any_of(observations_.begin(), observations_.end(), [t_s](const PendingObservation& p) {
    return !p.done && t_s >= p.start_s - kDragLookback_s && t_s <= p.end_s;
  });
  if (!near) return;
  const gnc::Telemetry& active = host[host.active_index()].out.telemetry;
  const Eigen::Vector3d assumed_rtn(0.0, active.drag_valid ? active.differential_drag_mps2 : 0.0, 0.0);
  drag_since_burn_.push_back({t_s + 0.5 * step_s_, (drag_difference_rtn(truth, t) - assumed_rtn) * step_s_});
}

// The budget of this step's alignment sample (sim/error_budget.hpp), from the active spacecraft's
// navigation solution scored this step; none without one.
std::optional<ErrorBudget> RunMetrics::budget_at(const TruthWorld& truth, const HostApplication& host, double t_s) const {
  const std::size_t active = host.active_index();
  const NavigationSample& nav = navigation_samples_[active];
  const std::optional<gnc::NavigationTelemetry>& record = host[active].out.navigation;
  if (!nav.valid || !record) return std::nullopt;
  const TruthSpacecraft& dsc = truth[0];
  const TruthSpacecraft& osc = truth[1];
  const Eigen::Matrix3d rtn_to_gcrf = core::gcrf_to_rtn_matrix(dsc.x_gcrf).transpose();
  BudgetInputs in;
  in.payload_true = {osc.payload_gcrf_m() - dsc.payload_gcrf_m(), osc.x_gcrf.v - dsc.x_gcrf.v};
  in.com_true = {osc.x_gcrf.r - dsc.x_gcrf.r, osc.x_gcrf.v - dsc.x_gcrf.v};
  in.com_estimated = {in.com_true.r + rtn_to_gcrf * nav.position_rtn_m, in.com_true.v + rtn_to_gcrf * nav.velocity_rtn_mps};
  in.lever_error = rtn_to_gcrf * (nav.antenna_rtn_m - nav.position_rtn_m);
  in.target_true = dsc.target_unit_gcrf;
  in.target_estimated = astro::apparent_target_unit_gcrf(aim_t0_ + t_s, record->dsc_gcrf, aim_geometry_.target_offset_rad);
  in.focal_distance_m = aim_geometry_.focal_distance_m;
  in.dsc_position = dsc.x_gcrf.r;
  if (last_burn_ && t_s >= last_burn_->t_s) {
    const core::StateVector response = hcw_impulse_response(last_burn_->dv_rtn_mps, last_burn_->n_radps, t_s - last_burn_->t_s);
    in.last_burn = {rtn_to_gcrf * response.r, rtn_to_gcrf * response.v};
  }
  const double n_radps = mean_motion_radps(dsc.x_gcrf);
  core::StateVector drag{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  for (const DragImpulse& d : drag_since_burn_) {
    if (d.t_s > t_s) continue;
    const core::StateVector response = hcw_impulse_response(d.dv_rtn_mps, n_radps, t_s - d.t_s);
    drag.r += response.r;
    drag.v += response.v;
  }
  in.drag_prediction = {rtn_to_gcrf * drag.r, rtn_to_gcrf * drag.v};
  return error_budget(in);
}

void RunMetrics::sample_alignment(PendingObservation& p, const TruthWorld& truth, const HostApplication& host, double t_s) {
  const TruthSpacecraft& dsc = truth[0];
  const TruthSpacecraft& osc = truth[1];
  const double worst_before = p.result.lateral_error_m;
  const bool first = p.result.samples == 0;
  const AlignmentSample sample = add_alignment_sample(p.result, osc.payload_gcrf_m(), osc.x_gcrf.v, dsc.payload_gcrf_m(),
                                                      dsc.x_gcrf.v, dsc.target_unit_gcrf, requirements_);
  if (first || sample.lateral_m > worst_before) p.budget = budget_at(truth, host, t_s);
  recorder_->alignment_sample(p.result.index, t_s, dsc.x_gcrf, dsc.q_body_to_gcrf, osc.x_gcrf, osc.q_body_to_gcrf,
                              dsc.target_unit_gcrf, sample);
  for (std::size_t k = 0; k < 2; ++k) {
    double& worst = p.result.payload_pointing_rad(static_cast<Eigen::Index>(k));
    worst = std::max(worst, payload_pointing_rad(truth[k]));
  }
}

void RunMetrics::close_observation(PendingObservation& p, double t_s) {
  p.done = true;
  const bool ok = p.result.success(requirements_);
  recorder_->observation(p.result, ok, p.budget);
  recorder_->event(t_s, "sim", "observation",
                   fmt::format("attempt {}: lateral {:.2f} mm, lateral velocity {:.3f} mm/s, focus {:.2f} mm: {}", p.result.index,
                               1e3 * p.result.lateral_error_m, 1e3 * p.result.lateral_velocity_mps, 1e3 * p.result.focus_error_m,
                               ok ? "success" : "failure"));
}

void RunMetrics::record(const TruthWorld& truth, const HostApplication& host, core::GpsTime t, double t_s, std::int64_t step,
                        std::int64_t output_every, const core::EarthGravityConstants& gravity, bool navigation, bool in_slew,
                        bool in_observation) {
  for (PendingObservation& p : observations_) {
    if (p.done) continue;
    if (t_s >= p.start_s && t_s <= p.end_s) sample_alignment(p, truth, host, t_s);
    else if (t_s > p.end_s) close_observation(p, t_s);
  }
  record_drag_prediction(truth, host, t, t_s);
  TimeseriesRow row = truth_geometry(truth[0].x_gcrf, truth[1].x_gcrf);
  min_sep_rn_m_ = std::min(min_sep_rn_m_, row.sep_rn_m);
  min_sep_3d_m_ = std::min(min_sep_3d_m_, row.sep_3d_m);
  if (step % output_every != 0) return;
  const HostedComponent& now = host[host.active_index()];
  add_truth_roe(truth[0].x_gcrf, truth[1].x_gcrf, gravity, row);
  row.t_s = t_s;
  row.mode = to_string(now.out.mode);
  row.active = now.name;
  row.has_margin = now.out.telemetry.safety_checked;
  row.safety_margin_m = now.out.telemetry.safety_margin_m;
  row.dv_dsc_mps = dv_total_mps_[0];
  row.dv_osc_mps = dv_total_mps_[1];
  add_drag(truth, t, now.out.telemetry, row);
  recorder_->timeseries(row);
  if (navigation) record_navigation_rows(host, t_s, in_slew, in_observation);
}

void RunMetrics::record_navigation_rows(const HostApplication& host, double t_s, bool in_slew, bool in_observation) {
  for (std::size_t k = 0; k < 2; ++k) {
    double fixed_fraction = 0.0;
    if (const std::optional<gnc::NavigationTelemetry>& record = host[k].out.navigation) {
      const gnc::NavigationCounters& c = record->counters;
      const std::int64_t epochs = c.epochs_joint + c.epochs_alone;
      if (epochs > rows_epochs_[k]) {
        fixed_fraction = static_cast<double>(c.epochs_fixed - rows_fixed_[k]) / static_cast<double>(epochs - rows_epochs_[k]);
      }
      rows_epochs_[k] = epochs;
      rows_fixed_[k] = c.epochs_fixed;
    }
    recorder_->navigation(t_s, host[k].name, navigation_samples_[k], fixed_fraction, in_slew, in_observation);
  }
}

void RunMetrics::add_to_summary(nlohmann::json& summary, const std::array<std::string_view, 2>& names) const {
  nlohmann::json list = nlohmann::json::array();
  int successes = 0, attempts = 0;
  for (const PendingObservation& p : observations_) {
    if (!p.done) continue;
    const bool ok = p.result.success(requirements_);
    successes += ok ? 1 : 0;
    ++attempts;
    list.push_back({{"index", p.result.index}, {"t_s", p.result.t_s}, {"lateral_error_m", p.result.lateral_error_m},
                    {"lateral_velocity_mps", p.result.lateral_velocity_mps}, {"focus_error_m", p.result.focus_error_m},
                    {"lateral_x_m", p.result.lateral_detector_m.x()}, {"lateral_y_m", p.result.lateral_detector_m.y()},
                    {"focus_signed_m", p.result.focus_signed_m}, {"success", ok}});
    if (p.budget) {
      nlohmann::json budget;
      for (int i = 0; i < kBudgetTerms; ++i) {
        const BudgetComponents& c = (*p.budget)[static_cast<std::size_t>(i)];
        budget[std::string(to_string(static_cast<BudgetTerm>(i)))] = {
            {"x_m", c.x_m}, {"y_m", c.y_m}, {"focus_m", c.focus_m}, {"velocity_x_mps", c.velocity_x_mps}, {"velocity_y_mps", c.velocity_y_mps}};
      }
      list.back()["budget"] = budget;
    }
  }
  summary["observations"] = list;
  summary["success_rate"] = attempts > 0 ? static_cast<double>(successes) / attempts : 0.0;
  nlohmann::json dv;
  for (std::size_t k = 0; k < 2; ++k) {
    nlohmann::json by_mode;
    for (int m = 0; m < gnc::kModeCount; ++m) by_mode[std::string(to_string(static_cast<gnc::Mode>(m)))] = dv_by_mode_mps_[k][static_cast<std::size_t>(m)];
    by_mode["total"] = dv_total_mps_[k];
    dv[std::string(names[k])] = by_mode;
  }
  summary["delta_v_mps"] = dv;
  summary["min_separation_rn_m"] = min_sep_rn_m_;
  summary["min_separation_3d_m"] = min_sep_3d_m_;
  for (std::size_t k = 0; k < 2; ++k) {
    // Wall time of each flight-component step through its binary interface (decoding, the step,
    // encoding) [us]: the flight rule's budget is a median <= 0.3 ms and a 99.9th percentile <= 5 ms.
    std::vector<float> sorted = step_us_[k];
    std::sort(sorted.begin(), sorted.end());
    const auto at = [&sorted](double q) {
      return sorted.empty() ? 0.0 : static_cast<double>(sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))]);
    };
    summary["flight_step_us"][std::string(names[k])] = {{"median", at(0.5)}, {"p99_9", at(0.999)}, {"max", at(1.0)}};
  }
}

// The navigation score (sim/navigation_score.hpp: the counters from the components' navigation
// telemetry records) with each component's rejected GPS messages (its telemetry record).
nlohmann::json RunMetrics::navigation_summary(const HostApplication& host) const {
  nlohmann::json out = navigation_score_.summary();
  for (std::size_t k = 0; k < 2; ++k) out[std::string(host[k].name)]["rejected_gps_messages"] = host[k].out.telemetry.rejected.of(gnc::Channel::kGps);
  return out;
}

}  // namespace visors::sim
