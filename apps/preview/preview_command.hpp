#pragma once
// `visors preview [SCENARIO] [--out DIR]`: runs a formation preview and reports it.

#include <string>

namespace visors::preview {

/// Returns the process exit code: 0 on success, 2 on bad input (message on stderr).
int run_preview_command(const std::string& scenario_path, const std::string& out_dir);

}  // namespace visors::preview
