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

core::Status validate_planner_chief(const astro::KeplerianElements& chief, const char* chief_name,
                                    const core::EarthGravityConstants& gravity) {
  if (const core::Status valid = astro::validate_keplerian(chief).status(); !valid) return valid.within(chief_name);
  if (chief.e >= 0.1) {
    return core::Status{core::Problem::kOutOfRange, "e", "must be below 0.1 (near-circular planners)"}.within(chief_name);
  }
  if (std::sin(chief.i) < 1e-6) return core::Status{core::Problem::kSingular, "i", "must not be equatorial"}.within(chief_name);
  if (!(gravity.mu > 0.0) || !(gravity.re > 0.0) || !std::isfinite(gravity.mu) || !std::isfinite(gravity.re) ||
      !std::isfinite(gravity.j2)) {
    return core::Status{core::Problem::kOutOfRange, "gravity", "mu and re must be finite and positive, j2 finite"};
  }
  return {};
}

core::Status validate_roe(const astro::RelativeOrbitalElements& roe, const char* name) {
  if (!roe.allFinite()) return core::Status{core::Problem::kNotFinite, name};
  if (roe.cwiseAbs().maxCoeff() > kMaxLinearRoe) {
    return core::Status{core::Problem::kOutOfRange, name,
                        "|dROE| above 1e-2 (a*dROE of tens of km) is outside the linear relative-motion model"};
  }
  return {};
}

}  // namespace visors::control
