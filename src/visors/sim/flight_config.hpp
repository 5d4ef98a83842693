#pragma once
// What each flight component is created with, and its record in the run directory
// (flight_config.json): the GNC configuration, the on-board navigation's settings (the CDGPS
// filter's among them) and both on-board force models (their configuration and the spacecraft
// properties the flight software is told). The simulator creates the components from this JSON
// (gnc/files/flight_config_json.hpp: in process, or as visors-fsw processes reading the file), so
// the file is the configuration as created. Nothing in it comes from a truth
// key (docs/truth-and-knowledge.md): dispersing the truth leaves it byte for byte the same
// (tests/sim/test_flight_config.cpp).

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/dynamics/force_model_config.hpp"
#include "visors/gnc/gnc_config.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::sim {

/// The GNC configuration of `craft` with its initial role.
gnc::GncConfig flight_gnc_config(const CampaignScenario& scenario, gnc::Spacecraft craft, bool active);

/// The properties the flight software is told of `craft` ([flight]).
dynamics::SpacecraftProperties flight_spacecraft_properties(const FlightKnowledge& knowledge, gnc::Spacecraft craft);

/// Both components' complete configuration: {"dsc": {...}, "osc": {...}}, each with "gnc",
/// "navigation" (with GPS navigation) and "force_models" {"dsc", "osc"}. Errors as
/// onboard_navigation_settings().
core::Result<nlohmann::json> flight_config_json(const CampaignScenario& scenario);

}  // namespace visors::sim
