#include "visors/sim/error_budget.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "visors/sim/alignment_metrics.hpp"

namespace visors::sim {
namespace {

// Lateral (x, y) and focus (z) components of r and v in the detector frame.
BudgetComponents components(const DetectorAxes& f, const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
  return {r.dot(f.x), r.dot(f.y), r.dot(f.z), v.dot(f.x), v.dot(f.y)};
}

}  // namespace

std::string_view to_string(BudgetTerm term) {
  switch (term) {
    case BudgetTerm::kNavigation: return "navigation";
    case BudgetTerm::kPhaseCentre: return "phase_centre";
    case BudgetTerm::kGeometry: return "geometry";
    case BudgetTerm::kTargetDirection: return "target_direction";
    case BudgetTerm::kLastBurn: return "last_burn";
    case BudgetTerm::kDragPrediction: return "drag_prediction";
    case BudgetTerm::kControlOther: return "control_other";
  }
  return "unknown";
}

ErrorBudget error_budget(const BudgetInputs& in) {
  const DetectorAxes frame = detector_axes(in.target_true, in.dsc_position);
  const Eigen::Vector3d navigation_r = in.com_estimated.r - in.com_true.r;  // d_e - d_c
  const Eigen::Vector3d navigation_v = in.com_estimated.v - in.com_true.v;
  const Eigen::Vector3d control_r = in.com_estimated.r - in.focal_distance_m * in.target_estimated;
  ErrorBudget out;
  const auto set = [&](BudgetTerm t, const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
    out[static_cast<std::size_t>(t)] = components(frame, r, v);
  };
  set(BudgetTerm::kNavigation, -(navigation_r + in.lever_error), -navigation_v);
  set(BudgetTerm::kPhaseCentre, in.lever_error, Eigen::Vector3d::Zero());
  set(BudgetTerm::kGeometry, in.payload_true.r - in.com_true.r, in.payload_true.v - in.com_true.v);
  set(BudgetTerm::kTargetDirection, in.focal_distance_m * (in.target_estimated - in.target_true), Eigen::Vector3d::Zero());
  set(BudgetTerm::kLastBurn, in.last_burn.r, in.last_burn.v);
  set(BudgetTerm::kDragPrediction, in.drag_prediction.r, in.drag_prediction.v);
  set(BudgetTerm::kControlOther, control_r - in.last_burn.r - in.drag_prediction.r,
      in.com_estimated.v - in.last_burn.v - in.drag_prediction.v);
  return out;
}

core::StateVector hcw_impulse_response(const Eigen::Vector3d& dv_rtn_mps, double n_radps, double dt_s) {
  const double nt = n_radps * dt_s, s = std::sin(nt), c = std::cos(nt);
  Eigen::Matrix3d rv, vv;
  rv << s / n_radps, 2.0 * (1.0 - c) / n_radps, 0.0,  //
      -2.0 * (1.0 - c) / n_radps, (4.0 * s - 3.0 * nt) / n_radps, 0.0,  //
      0.0, 0.0, s / n_radps;
  vv << c, 2.0 * s, 0.0,  //
      -2.0 * s, 4.0 * c - 3.0, 0.0,  //
      0.0, 0.0, c;
  return {rv * dv_rtn_mps, vv * dv_rtn_mps};
}

}  // namespace visors::sim
