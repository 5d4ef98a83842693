#include "visors/sim/ideal_navigation.hpp"

#include <cmath>

#include "visors/core/rtn_frame.hpp"

namespace visors::sim {

IdealNavigation::IdealNavigation(const NavigationErrorSettings& settings, RandomStream rng)
    : settings_(settings), rng_(std::move(rng)) {
  const double axis = 1.0 / std::sqrt(3.0);
  sigma_.segment<3>(0).setConstant(settings.absolute_position_m * axis);
  sigma_.segment<3>(3).setConstant(settings.absolute_velocity_mps * axis);
  sigma_.segment<3>(6).setConstant(settings.relative_position_m * axis);
  sigma_.segment<3>(9).setConstant(settings.relative_velocity_mps * axis);
  for (int i = 0; i < 12; ++i) error_(i) = rng_.normal(sigma_(i));  // stationary start
  // The reported covariance has a floor (1 mm, 1 um/s per axis): a zero covariance would tell the
  // flight software its knowledge is perfect, which the MPC's Mahalanobis test and the
  // safety check cannot use.
  Eigen::Matrix<double, 6, 1> reported = sigma_.segment<6>(6);
  reported.head<3>() = reported.head<3>().cwiseMax(1e-3);
  reported.tail<3>() = reported.tail<3>().cwiseMax(1e-6);
  covariance_.diagonal() = reported.array().square().matrix();
}

void IdealNavigation::advance(double dt) {
  if (!(dt > 0.0)) return;
  const double phi = std::exp(-dt / settings_.correlation_time_s);
  const double drive = std::sqrt(1.0 - phi * phi);
  for (int i = 0; i < 12; ++i) error_(i) = phi * error_(i) + drive * rng_.normal(sigma_(i));
}

gnc::NavigationSolution IdealNavigation::solve(core::GpsTime t, const core::StateVector& dsc_gcrf,
                                               const core::StateVector& osc_gcrf, double dt) {
  advance(dt);
  core::RelativeStateRtn relative = core::relative_state_rtn(dsc_gcrf, osc_gcrf);
  relative.dr_rtn += error_.segment<3>(6);
  relative.dv_rtn += error_.segment<3>(9);
  gnc::NavigationSolution out;
  out.t = t;
  out.chief_gcrf = core::StateVector{dsc_gcrf.r + error_.segment<3>(0), dsc_gcrf.v + error_.segment<3>(3)};
  out.deputy_gcrf = core::deputy_state_gcrf(out.chief_gcrf, relative);
  out.relative_covariance_rtn = covariance_;
  return out;
}

}  // namespace visors::sim
