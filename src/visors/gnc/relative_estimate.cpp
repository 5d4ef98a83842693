#include "visors/gnc/relative_estimate.hpp"

#include <Eigen/LU>

#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::gnc {

core::Outcome<RelativeEstimate> estimate_from_navigation(const NavigationSolution& navigation,
                                                        const core::EarthGravityConstants& gravity) {
  const auto chief_osc = astro::cartesian_to_keplerian(navigation.chief_gcrf.r, navigation.chief_gcrf.v, gravity.mu);
  if (!chief_osc.ok()) return chief_osc.status().within("navigation.chief_gcrf");
  const auto deputy_osc = astro::cartesian_to_keplerian(navigation.deputy_gcrf.r, navigation.deputy_gcrf.v, gravity.mu);
  if (!deputy_osc.ok()) return deputy_osc.status().within("navigation.deputy_gcrf");
  const auto chief_mean = astro::mean_from_osculating(*chief_osc, gravity);
  if (!chief_mean.ok()) return chief_mean.status().within("navigation.chief_gcrf");
  const auto deputy_mean = astro::mean_from_osculating(*deputy_osc, gravity);
  if (!deputy_mean.ok()) return deputy_mean.status().within("navigation.deputy_gcrf");
  const auto roe = astro::roe_from_keplerian(*chief_mean, *deputy_mean);
  if (!roe.ok()) return roe.status().within("navigation");

  RelativeEstimate out;
  out.t = navigation.t;
  out.chief_gcrf = navigation.chief_gcrf;
  out.rtn_to_gcrf = core::gcrf_to_rtn_matrix(navigation.chief_gcrf).transpose();
  out.chief_mean = *chief_mean;
  out.roe_mean = *roe;
  const astro::RoeToRtnMatrix c = astro::roe_to_rtn_matrix(*chief_osc, gravity.mu);
  const Eigen::Matrix<double, 6, 6> c_inv = c.partialPivLu().inverse();
  out.roe_covariance = c_inv * navigation.relative_covariance_rtn * c_inv.transpose();
  out.roe_covariance = 0.5 * (out.roe_covariance + out.roe_covariance.transpose()).eval();
  return out;
}

}  // namespace visors::gnc
