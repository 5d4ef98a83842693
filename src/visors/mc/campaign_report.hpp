#pragma once
// The HTML report of a Monte Carlo campaign (`visors mc report`): one self-contained page with, per
// swept parameter, the sensitivity figure of Guffanti et al., AAS 23-149, 2023, sec. 5, "Monte
// Carlo alignment performances" (whisker plots of the lateral alignment error over the attempts of
// each value, and their success percentage against the 20 % requirement of its sec. 2), the
// dispersion of the alignment errors in the detector's frame, delta-v statistics, the failed runs
// with their reasons, and the campaign's provenance (program version, data files with checksums).

#include <filesystem>
#include <string>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/mc/results_store.hpp"

namespace visors::mc {

/// The attempts of one value of one sweep (key empty and value "all runs" without sweeps).
struct ValueSuccess {
  std::string key;
  std::string value;  // as the campaign file wrote it
  long successes = 0;
  long attempts = 0;
};

/// Successes per sweep value over the runs that ended, in the campaign's order (sweeps and values
/// as the file lists them), the grouping of the report's figure.
std::vector<ValueSuccess> success_by_value(const std::vector<StoredRun>& runs);

/// Writes `out_dir`/report.html from the store, and each sweep's sensitivity figure alone as
/// `out_dir`/sensitivity_N.svg (N the sweep's index in the campaign file; an image for other
/// documents); returns the page's path.
core::Result<std::filesystem::path> write_campaign_report(ResultsStore& store, const std::filesystem::path& out_dir);

}  // namespace visors::mc
