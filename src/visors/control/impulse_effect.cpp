#include "visors/control/impulse_effect.hpp"

#include <cmath>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_stm.hpp"

namespace visors::control {

Eigen::Matrix<double, 6, 3> impulse_effect(const astro::KeplerianElements& chief_mean_t0, double t, double t_ref,
                                           const core::EarthGravityConstants& gravity) {
  const astro::KeplerianElements chief_t = astro::propagate_mean_j2(chief_mean_t0, t, gravity);
  return astro::j2_roe_stm(chief_t, t_ref - t, gravity) * astro::control_input_matrix(chief_t, gravity.mu);
}

astro::RelativeOrbitalElements predict_roe(const astro::KeplerianElements& chief_mean_t0,
                                           const astro::RelativeOrbitalElements& roe0,
                                           const std::vector<Impulse>& impulses, double t_ref,
                                           const core::EarthGravityConstants& gravity) {
  astro::RelativeOrbitalElements roe = astro::j2_roe_stm(chief_mean_t0, t_ref, gravity) * roe0;
  for (const Impulse& i : impulses) roe += impulse_effect(chief_mean_t0, i.t, t_ref, gravity) * i.dv_rtn;
  return roe;
}

core::Result<bool> validate_planner_chief(const astro::KeplerianElements& chief, const std::string& chief_name,
                                          const core::EarthGravityConstants& gravity) {
  const auto valid = astro::validate_keplerian(chief);
  if (!valid.ok()) return core::Error{chief_name + "." + valid.error().field, valid.error().message};
  if (chief.e >= 0.1) return core::Error{chief_name + ".e", "must be below 0.1 (near-circular planners)"};
  if (std::sin(chief.i) < 1e-6) return core::Error{chief_name + ".i", "must not be equatorial"};
  if (!(gravity.mu > 0.0) || !(gravity.re > 0.0) || !std::isfinite(gravity.mu) || !std::isfinite(gravity.re) ||
      !std::isfinite(gravity.j2)) {
    return core::Error{"gravity", "mu and re must be finite and positive, j2 finite"};
  }
  return true;
}

core::Result<bool> validate_roe(const astro::RelativeOrbitalElements& roe, const std::string& name) {
  if (!roe.allFinite()) return core::Error{name, "must be finite"};
  if (roe.cwiseAbs().maxCoeff() > kMaxLinearRoe) {
    return core::Error{name, "|dROE| above 1e-2 (a*dROE of tens of km) is outside the linear relative-motion model"};
  }
  return true;
}

}  // namespace visors::control
