#pragma once
// The TOML scenario of `visors propagate`: epoch, initial state, integrator, spacecraft, forces,
// maneuvers, outputs. See data/scenarios/propagate_chief.toml for a commented example.

#include <filesystem>
#include <string>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/dynamics/force_model_config.hpp"
#include "visors/dynamics/orbit_propagator.hpp"

namespace visors::propagate {

struct PropagateScenario {
  core::GpsTime epoch;
  core::StateVector initial_gcrf;  // osculating [m, m/s]
  double duration = 5700.0;        // [s]
  double output_step = 60.0;       // [s]
  dynamics::PropagatorSettings propagator;
  dynamics::SpacecraftProperties spacecraft;
  dynamics::ForceModelConfig forces;
  std::vector<dynamics::ImpulsiveManeuver> maneuvers;  // sorted by time
  std::string name = "spacecraft";  // output file stem and OEM OBJECT_NAME
};

core::Result<PropagateScenario> parse_propagate_scenario(const std::string& toml_text);
core::Result<PropagateScenario> load_propagate_scenario(const std::filesystem::path& path);

}  // namespace visors::propagate
