#include "control/j2_numerical_propagation.hpp"

#include <gtest/gtest.h>

#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/orbit_propagator.hpp"

namespace visors::control::test {

astro::RelativeOrbitalElements propagate_j2_numerically(const astro::KeplerianElements& chief_mean0,
                                                        const astro::RelativeOrbitalElements& roe0,
                                                        const std::vector<Impulse>& impulses, double tf) {
  const core::EarthGravityConstants g;
  dynamics::ForceModelConfig c = dynamics::ForceModelConfig::gravity_only(2, 0);
  auto forces = dynamics::files::load_force_model(c, {});
  EXPECT_TRUE(forces.ok()) << forces.error().describe();
  dynamics::ForceModel fm = std::move(forces).value();
  dynamics::PropagatorSettings s;
  s.integrator = dynamics::IntegratorKind::kDormandPrince87;
  auto prop = dynamics::OrbitPropagator::create(fm, s);
  EXPECT_TRUE(prop.ok());
  dynamics::OrbitPropagator p = std::move(prop).value();
  const core::GpsTime t0 = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();

  const astro::KeplerianElements deputy_mean0 = astro::deputy_from_roe(chief_mean0, roe0).value();
  const core::StateVector xc0 = astro::cartesian_from_keplerian(astro::osculating_from_mean(chief_mean0, g).value(), g.mu);
  const core::StateVector xd0 = astro::cartesian_from_keplerian(astro::osculating_from_mean(deputy_mean0, g).value(), g.mu);
  std::vector<dynamics::ImpulsiveManeuver> burns;
  for (const Impulse& imp : impulses) burns.push_back({t0 + imp.t, imp.dv_rtn, dynamics::ManeuverFrame::kRtn});
  const core::StateVector xcf = p.propagate_to(t0, xc0, t0 + tf).value();
  const core::StateVector xdf = p.propagate_to(t0, xd0, t0 + tf, burns).value();
  const auto mean_of = [&](const core::StateVector& x) {
    return astro::mean_from_osculating(astro::cartesian_to_keplerian(x.r, x.v, g.mu).value(), g).value();
  };
  return astro::roe_from_keplerian(mean_of(xcf), mean_of(xdf)).value();
}


}  // namespace visors::control::test
