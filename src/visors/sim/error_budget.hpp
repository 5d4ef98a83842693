#pragma once
// The error budget of an observation attempt (ground side of the simulator): the true alignment
// error at a sample, d - f s (d the payload separation OSC minus DSC, s the target's true apparent
// direction, f the focal distance; sim/alignment_metrics.hpp), split into what each source put
// there. With d_c the true centres of mass' separation, d_e the flight software's estimate of it
// (the active spacecraft's navigation), s_e the target direction the flight software computes
// from its estimate, and the lever error L = C_osc (p_osc - l_osc) - C_dsc (p_dsc - l_dsc) (p the
// estimated phase-centre offsets, l the true ones; sim/navigation_score.hpp):
//   navigation (antennas)  -(d_e - d_c + L)   the relative antenna position's error, reversed
//   phase centre           +L                 the offsets' estimate error
//   geometry               d - d_c            the payload points from the true centres of mass
//                                             (mounting, centre-of-mass variation), which the
//                                             flight software aims as if at the centres of mass
//   target direction       f (s_e - s)        the aim's direction error
//   last burn              the last impulse's execution error (true minus intended velocity
//                          change), carried to the sample by the Hill-Clohessy-Wiltshire
//                          transition over the time since it
//   drag prediction        the true differential drag minus the one the flight software's
//                          planners assumed (its estimate along T), since the last burn, each
//                          step's difference an impulse carried to the sample the same way
//   control, other         (d_e - f s_e) - last burn - drag prediction: what the flight software
//                          itself would see with perfect navigation (the navigation error the last
//                          burns were planned from, earlier burns, planning)
// The seven add up to d - f s exactly. Velocities likewise, with w = d', w_c = d_c', w_e = d_e':
// navigation -(w_e - w_c), geometry w - w_c, last burn, drag prediction, control other w_e - last
// burn - drag prediction (the aim's velocity is zero). Each term is given as lateral (x, y: the detector frame of
// sim/alignment_metrics.hpp) and focus (along s) components.

#include <array>
#include <string_view>

#include <Eigen/Core>

#include "visors/core/state_vector.hpp"

namespace visors::sim {

enum class BudgetTerm : int {
  kNavigation,
  kPhaseCentre,
  kGeometry,
  kTargetDirection,
  kLastBurn,
  kDragPrediction,
  kControlOther
};
inline constexpr int kBudgetTerms = 7;
/// "navigation", "phase_centre", "geometry", "target_direction", "last_burn", "drag_prediction",
/// "control_other".
std::string_view to_string(BudgetTerm term);

/// One sample's inputs, GCRF [m, m/s].
struct BudgetInputs {
  core::StateVector payload_true;        // payload points, OSC minus DSC
  core::StateVector com_true;            // centres of mass, OSC minus DSC
  core::StateVector com_estimated;       // the flight software's estimate of com_true
  Eigen::Vector3d lever_error = Eigen::Vector3d::Zero();  // L (file comment)
  Eigen::Vector3d target_true = Eigen::Vector3d::UnitX();       // s (unit)
  Eigen::Vector3d target_estimated = Eigen::Vector3d::UnitX();  // s_e (unit)
  double focal_distance_m = 40.0;
  core::StateVector last_burn;           // the last burn's effect at the sample (relative)
  core::StateVector drag_prediction;     // the drag prediction error's effect at the sample (relative)
  Eigen::Vector3d dsc_position = Eigen::Vector3d::UnitX();  // the DSC, for the detector frame's vertical
};

struct BudgetComponents {
  double x_m = 0.0, y_m = 0.0, focus_m = 0.0;        // position: lateral x, y and along s
  double velocity_x_mps = 0.0, velocity_y_mps = 0.0;  // lateral velocity x, y
};

using ErrorBudget = std::array<BudgetComponents, kBudgetTerms>;

/// The budget of one sample (file comment).
ErrorBudget error_budget(const BudgetInputs& in);

/// The relative state change at dt [s] after an impulse dv_rtn [m/s] of the deputy, in the chief's
/// RTN frame at the impulse (Hill-Clohessy-Wiltshire, mean motion n [rad/s]): r = Phi_rv dv,
/// v = Phi_vv dv (Vallado, Fundamentals of Astrodynamics, 4th ed., eq. 6-66).
core::StateVector hcw_impulse_response(const Eigen::Vector3d& dv_rtn_mps, double n_radps, double dt_s);

}  // namespace visors::sim
