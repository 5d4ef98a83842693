#include "visors/sim/formation_initial_state.hpp"

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"

namespace visors::sim {

namespace {

core::Result<core::StateVector> from_mean(const astro::KeplerianElements& mean, const core::EarthGravityConstants& g) {
  const auto osc = astro::osculating_from_mean(mean, g);
  if (!osc.ok()) return osc.error();
  return astro::cartesian_from_keplerian(*osc, g.mu);
}

}  // namespace

core::Result<FormationState> initial_formation_state(const CampaignScenario& s) {
  const core::EarthGravityConstants& g = s.gnc.gravity;
  auto dsc = from_mean(s.chief_mean, g);
  if (!dsc.ok()) return core::Error{"chief", dsc.error().describe()};
  const auto deputy_mean = astro::deputy_from_roe(s.chief_mean, s.initial_roe_m / s.chief_mean.a);
  if (!deputy_mean.ok()) return core::Error{"formation.initial_roe_m", deputy_mean.error().describe()};
  auto osc = from_mean(*deputy_mean, g);
  if (!osc.ok()) return core::Error{"formation.initial_roe_m", osc.error().describe()};
  return FormationState{*dsc, *osc};
}

}  // namespace visors::sim
