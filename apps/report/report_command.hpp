#pragma once
// `visors report DIR`: renders DIR/report.html from the run directory's other files and prints
// its path.

#include <string>

namespace visors::report {

/// Returns the process exit code: 0 on success, 2 on a bad directory or malformed run files.
int run_report_command(const std::string& run_dir);

}  // namespace visors::report
