#pragma once
// Force-model and spacecraft configuration from TOML (ground side). Layout (every key optional;
// `preset` chooses the starting values, the other keys override them):
//
//   [spacecraft]              mass [kg], drag_area [m^2], cd, srp_area [m^2], cr
//   [forces]                  preset = "truth" | "onboard", sun, moon, empirical_rtn = [3] m/s^2
//   [forces.gravity]          model (ICGEM path), degree, order, allow_embedded_fallback
//   [forces.drag]             enabled, atmosphere = "harris-priester" | "harris-priester-max" |
//                             "nrlmsise00", cosine_exponent, density_scale, space_weather
//                             (CelesTrak CSV), f107, f107a, ap (used when no space_weather file),
//                             nrlmsise00_coefficients (the model's tables, data-relative),
//                             ap_history (NRLMSISE-00 driven by the 3-hourly ap; default true)
//   [forces.srp]              enabled, pressure_1au [N/m^2], shadow = "none" | "cylindrical" | "conical"
//   [forces.earth_frame]      eop (finals2000A file), refresh_interval [s]
//
// Errors name the dotted field; unknown keys are rejected.

#include <toml++/toml.h>

#include "visors/core/result.hpp"
#include "visors/dynamics/force_model_config.hpp"

namespace visors::config {

/// Reads `forces` (the [forces] table; nullptr: the onboard preset).
core::Result<dynamics::ForceModelConfig> force_model_config_from_toml(const toml::table* forces,
                                                             const std::string& section = "forces");

/// Reads a [spacecraft] table (nullptr: the defaults); every value must be > 0.
core::Result<dynamics::SpacecraftProperties> spacecraft_from_toml(const toml::table* spacecraft,
                                                        const std::string& section = "spacecraft");

}  // namespace visors::config
