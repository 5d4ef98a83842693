#pragma once
// Reading daily space weather from a CelesTrak CSV file (the SW-All.csv layout,
// https://celestrak.org/SpaceData/SpaceWx-format.php), e.g.
// data/space_weather/SW-Observed_2024-07-01_2025-01-31.csv, into the flight layer's
// dynamics::SpaceWeatherTable. Ground side (visors_dynamics_files).
//
// Columns are found by their header names (DATE, F10.7_OBS, F10.7_OBS_CENTER81, AP_AVG,
// AP1..AP8); others are ignored. Rows must be consecutive UTC days with every used field filled:
// only observed data are accepted (trim CelesTrak's predicted blocks, whose ap fields are blank).

#include <filesystem>

#include "visors/core/result.hpp"
#include "visors/dynamics/space_weather.hpp"

namespace visors::dynamics::files {

/// Parses the CSV. Errors name the line ("line N") and the column (by header name).
core::Result<SpaceWeatherTable> read_space_weather_file(const std::filesystem::path& path);

}  // namespace visors::dynamics::files
