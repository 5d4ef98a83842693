#include "control/impulse_effect.hpp"

#include "astro/control_input_matrix.hpp"
#include "astro/j2_secular.hpp"
#include "astro/roe_stm.hpp"

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

}  // namespace visors::control
