#pragma once
// Reading a Harris-Priester density table from CSV into the flight layer's
// dynamics::HarrisPriesterTable. Ground side (visors_dynamics_files).

#include <filesystem>

#include "visors/core/result.hpp"
#include "visors/dynamics/harris_priester.hpp"

namespace visors::dynamics::files {

/// Reads the CSV of data/atmosphere/harris_priester_mg_table3-8.csv: a header naming the
/// columns altitude_km, rho_min_kg_per_m3, rho_max_kg_per_m3 (found by name; other columns are
/// ignored), then one row per node. Errors name the line (field "line N") and the column, for
/// malformed numbers, missing columns, non-increasing heights, non-positive densities,
/// rho_min > rho_max, fewer than 2 rows; "f107" for a non-positive or non-finite level. The rules
/// are those of validate_harris_priester_table.
core::Result<HarrisPriesterTable> read_harris_priester_table(const std::filesystem::path& path,
                                                             double f107);

}  // namespace visors::dynamics::files
