#pragma once
// Ideal navigation: the navigation solution is the truth plus errors of a configured size, for
// control-only studies (defaults: docs/requirements.md#navigation-defaults). The errors are
// first-order Gauss-Markov processes (a filter's error is correlated in time, not white), per axis
// with the 3D 1-sigma split evenly over the three axes (sigma_axis = sigma_3d / sqrt(3)):
//   e(t + dt) = phi e(t) + sigma_axis sqrt(1 - phi^2) w,  phi = exp(-dt / tau),  w ~ N(0, 1),
// started from the stationary distribution, so e has the configured sigma at every time.
// Absolute errors perturb the chief (DSC) state in GCRF; relative errors perturb the deputy's
// state relative to the chief in the chief's RTN (position, and rate in the rotating frame), and
// the deputy estimate is rebuilt from the perturbed chief and relative states. The reported
// covariance is the configured diagonal one.

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

class IdealNavigation {
 public:
  IdealNavigation(const NavigationErrorSettings& settings, RandomStream rng);

  /// The solution at t from the true states; dt: time since the previous call [s] (0 the first time).
  gnc::NavigationSolution solve(core::GpsTime t, const core::StateVector& dsc_gcrf, const core::StateVector& osc_gcrf,
                                double dt);

 private:
  void advance(double dt);

  NavigationErrorSettings settings_;
  RandomStream rng_;
  Eigen::Matrix<double, 12, 1> error_ = Eigen::Matrix<double, 12, 1>::Zero();  // abs r, abs v, rel r, rel v
  Eigen::Matrix<double, 12, 1> sigma_ = Eigen::Matrix<double, 12, 1>::Zero();
  Eigen::Matrix<double, 6, 6> covariance_ = Eigen::Matrix<double, 6, 6>::Zero();
};

}  // namespace visors::sim
