#pragma once
// The truth initial states of both spacecraft of a scenario: the DSC (chief) from its mean
// elements, the OSC (deputy) from the initial mean ROE, each converted to osculating elements with
// the first-order J2 theory and then to GCRF position and velocity.

#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::sim {

struct FormationState {
  core::StateVector dsc_gcrf;  // [m, m/s]
  core::StateVector osc_gcrf;  // [m, m/s]
};

/// Errors name "chief" or "formation.initial_roe_m".
core::Result<FormationState> initial_formation_state(const CampaignScenario& scenario);

}  // namespace visors::sim
