#pragma once
// The run report: one self-contained HTML file (inline CSS and SVG, no scripts, no network)
// rendered from a run directory's files alone (docs/run-directory.md), so it can be re-rendered
// or compared later. `visors run` calls write_report at the end of a run; `visors report DIR`
// re-renders it.
//
// Size: figures are drawn from every row, but each series is reduced to what its pixels can show
// while the SVG is written (decimate.hpp): time series keep the first, lowest, highest and last
// sample of each pixel column; trajectories are snapped to a 1 px grid, drop retraced segments
// and are capped at a point budget. A 35-orbit run at 10 s (~20,000 rows) gives ~0.6 MB.

#include <filesystem>
#include <string>

#include "visors/core/result.hpp"
#include "visors/report/run_data.hpp"

namespace visors::report {

/// The HTML document for the run in `run_dir`. Errors: timeseries.csv or summary.json missing or
/// malformed, a malformed observations.csv or events.csv (each error names the file, and the line
/// and column of a bad cell).
core::Result<std::string> render_report(const std::filesystem::path& run_dir);

/// The HTML document for an already loaded run.
std::string render_report(const RunData& run);

/// Renders the report and writes it to `run_dir`/report.html; returns that path.
core::Result<std::filesystem::path> write_report(const std::filesystem::path& run_dir);

}  // namespace visors::report
