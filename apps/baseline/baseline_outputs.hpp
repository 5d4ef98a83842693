#pragma once
// The outputs of `visors baseline`: baseline.csv, summary.json, baseline.html, and the overview
// printed on the terminal.

#include <nlohmann/json.hpp>

#include "apps/baseline/baseline_command.hpp"
#include "visors/baseline/baseline_processor.hpp"
#include "visors/core/result.hpp"

namespace visors::baseline_app {

struct BaselineRun {
  const BaselineOptions& options;
  const baseline::BaselineSettings& settings;
  const baseline::BaselineInputs& inputs;
  const baseline::BaselineResult& result;
  double wall_time_s = 0.0;  // reading, processing (not writing) [s]
};

/// The summary.json content (statistics over the epochs; fields in docs/cli/baseline.md).
nlohmann::json baseline_summary(const BaselineRun& run);

/// Writes the three files into run.options.out (`summary` is baseline_summary(run)); Error names
/// the file.
core::Result<bool> write_outputs(const BaselineRun& run, const nlohmann::json& summary);

/// A few lines on stdout from the summary: epochs per status, fix rate, the last solution.
void print_overview(const BaselineRun& run, const nlohmann::json& summary);

/// The HTML page (baseline_page.cpp).
std::string baseline_page(const BaselineRun& run, const nlohmann::json& summary);

}  // namespace visors::baseline_app
