#pragma once
// `visors baseline ROVER.obs BASE.obs --nav NAV [--nav NAV2] --base-ecef X Y Z [--mode
// static|kinematic] [--freq L1|L1L2] [--elevation-mask DEG] [--ar off|continuous|hold]
// [--out DIR]`: post-processed differential GPS between two ground receivers
// (src/visors/baseline/baseline_processor.hpp). Writes DIR/baseline.csv (one row per paired epoch),
// DIR/summary.json and DIR/baseline.html.

#include <array>
#include <string>
#include <vector>

namespace visors::baseline_app {

struct BaselineOptions {
  std::string rover, base;
  std::vector<std::string> nav;
  std::vector<double> base_ecef;  // 3 values [m]
  std::string mode = "static";
  std::string freq = "L1L2";
  double elevation_mask_deg = 10.0;
  std::string ar = "continuous";
  std::string out = "out/baseline";
};

/// Returns the process exit code: 0 on success, 2 on bad input (the message names the option or
/// the file and line), 1 when the outputs cannot be written.
int run_baseline_command(const BaselineOptions& options);

}  // namespace visors::baseline_app
