#pragma once
// Which data files a scenario reads (ground side): each file key of the scenario with the file
// found on the data search path, its size and a checksum, or not found (the run then uses an
// embedded default and says so as a warning). Recorded in summary.json and in a Monte Carlo
// campaign's store, so that a result can be traced to the data it was computed from.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::sim {

struct DataFileUse {
  std::string key;       // the scenario key naming it ("gnss.nav_file")
  std::string name;      // as the scenario names it
  std::string path;      // where it was found; empty when not found
  std::int64_t size = 0;
  std::string checksum;  // FNV-1a 64 of its bytes, 16 hex digits (a change detector, not a cryptographic hash)
};

/// Size and FNV-1a 64 checksum of a file (Fowler, Noll & Vo; offset basis 0xcbf29ce484222325,
/// prime 0x100000001b3).
core::Result<DataFileUse> describe_data_file(const std::filesystem::path& path);

/// The files of the scenario's keys gnss.nav_file, forces.gravity.model,
/// forces.drag.nrlmsise00_coefficients (when the truth's drag is NRLMSISE-00),
/// forces.drag.space_weather and forces.earth_frame.eop (those set), found or not.
std::vector<DataFileUse> data_files_of(const CampaignScenario& scenario);

}  // namespace visors::sim
