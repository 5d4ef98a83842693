#pragma once
// Impulsive maneuvers as the planners produce them and the buffer, the flight component and the
// simulator consume them: a time and a velocity change in the RTN frame of the maneuvering
// (deputy) spacecraft, approximated by the chief's RTN at the planners' first order.

#include <vector>

#include <Eigen/Core>

#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/result.hpp"

namespace visors::control {

struct Impulse {
  double t = 0.0;                                  // time since the plan's epoch t0 [s]
  Eigen::Vector3d dv_rtn = Eigen::Vector3d::Zero();  // [m/s]
};

/// A planner's answer: impulses sorted by time, their total |dv| and, when the planner knows it,
/// the lower bound on the total delta-v of the same boundary value problem.
struct ManeuverPlan {
  std::vector<Impulse> impulses;
  double dv_total_mps = 0.0;        // sum of |dv_rtn| [m/s]
  double dv_lower_bound_mps = 0.0;  // [m/s], 0 when not computed
  astro::RelativeOrbitalElements roe_final_predicted = astro::RelativeOrbitalElements::Zero();  // [-]
};

/// Sum of the impulse norms [m/s].
double total_delta_v(const std::vector<Impulse>& impulses);

/// Checks finiteness and time order (t non-decreasing, within [t_min, t_max]); the error names
/// "impulses[k].t" or "impulses[k].dv_rtn".
core::Result<std::vector<Impulse>> validate_impulses(std::vector<Impulse> impulses, double t_min, double t_max);

}  // namespace visors::control
