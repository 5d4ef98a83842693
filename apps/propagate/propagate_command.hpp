#pragma once
// `visors propagate SCENARIO.toml [--out DIR]`: propagates one spacecraft and writes its
// ephemeris as CSV and CCSDS OEM, plus summary.json.

#include <string>

namespace visors::propagate {

/// Returns the process exit code: 0 on success, 2 on bad input or a failed propagation.
int run_propagate_command(const std::string& scenario_path, const std::string& out_dir);

}  // namespace visors::propagate
