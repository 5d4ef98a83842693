#pragma once
// Data search path: reference data files (gravity fields, EOP, space weather, GPS ephemerides)
// are found at run time through VISORS_DATA_PATH (':'-separated folders), then the repository's
// own data/ folder, which ships what the default scenarios and the tests read (3 MB; provenance
// and checksums in data/SOURCES.md), then its installed copy (<prefix>/share/visors/data, for a
// program linked with the installed package once the source tree is gone). Ground side (visors_core_files): flight code gets the data,
// never a path.

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace visors::core::files {

/// The folders searched, in order: each entry of VISORS_DATA_PATH, the repository's data/, the
/// installed data (`<prefix>/share/visors/data`).
std::vector<std::filesystem::path> data_search_path();

/// Finds `relative` (e.g. "eop/finals2000A_2024-07-01_2025-01-31.txt") in the search path.
/// An absolute or existing path is returned as is. nullopt when found nowhere.
std::optional<std::filesystem::path> find_data_file(const std::string& relative);

}  // namespace visors::core::files
