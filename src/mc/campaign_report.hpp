#pragma once
// The HTML report of a Monte Carlo campaign (`visors mc report`): one self-contained page with,
// per swept parameter, the mission paper's sensitivity figure (whisker plots of the lateral
// alignment error over the attempts of each value, and their success percentage against the 20 %
// requirement), the dispersion of the alignment errors in the detector's frame, delta-v
// statistics, the failed runs with their reasons, and the campaign's provenance (program version,
// data files with checksums).

#include <filesystem>

#include "core/status.hpp"
#include "mc/results_store.hpp"

namespace visors::mc {

/// Writes `out_dir`/report.html from the store; returns its path.
core::Result<std::filesystem::path> write_campaign_report(ResultsStore& store, const std::filesystem::path& out_dir);

}  // namespace visors::mc
