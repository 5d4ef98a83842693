#pragma once
// The flight configuration as a file (flight_config.json, docs/run-directory.md): what one
// spacecraft's flight component is created with, as the ground uploads it. The simulator writes
// it and creates its in-process components from it (sim/flight_config.hpp); `visors-fsw`
// (apps/fsw/) reads it and creates the same component in its own process. Both go through
// make_component() below, so a component of either kind starts from the same values, bit for bit
// (JSON numbers are written as the shortest text that reads back to the same double).
//
// One component's object: "gnc" (gnc::GncConfig), and with on-board navigation "navigation"
// (gnc::OnboardNavigationSettings) and "force_models" {"config": the on-board
// dynamics::ForceModelConfig, "dsc", "osc": the spacecraft properties the software is told}.
// Every field of a struct under its name in the struct. Ground side (the gnc layer's files/):
// reads files and the data search path (the force models' gravity field and atmosphere tables).

#include <filesystem>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/dynamics/force_model_config.hpp"
#include "visors/gnc/gnc_config.hpp"
#include "visors/gnc/onboard_navigation.hpp"
#include "visors/gnc/record_interface.hpp"

namespace visors::gnc::files {

/// What a component with on-board navigation is given besides its GNC configuration.
struct NavigationSetup {
  OnboardNavigationSettings settings;  // settings.filter.local: the component's own spacecraft
  dynamics::ForceModelConfig force_model;  // both spacecraft's on-board force model
  dynamics::SpacecraftProperties dsc, osc;  // what the software is told of each spacecraft
};

/// One spacecraft's flight component as created.
struct ComponentSetup {
  GncConfig gnc;
  std::optional<NavigationSetup> navigation;  // none: the navigation solution comes from the host
};

/// The component's JSON object (file comment).
nlohmann::json to_json(const ComponentSetup& setup);

/// Reads a component's JSON object. Errors name the key (`field`: "gnc", "navigation" or
/// "force_models", the message nlohmann's, naming the key or the type that is wrong).
core::Result<ComponentSetup> component_setup_from_json(const nlohmann::json& component);

/// Reads `craft`'s ("dsc" or "osc") object of a flight_config.json. Errors name the file.
core::Result<ComponentSetup> read_component_setup(const std::filesystem::path& file, std::string_view craft);

/// Creates the component: the on-board force models loaded (the data search path), the
/// navigation, then the component behind its binary channels. Errors name the part.
core::Result<RecordInterface> make_component(const ComponentSetup& setup);

}  // namespace visors::gnc::files
