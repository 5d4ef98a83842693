#include "apps/report/report_command.hpp"

#include <filesystem>

#include <fmt/core.h>

#include "visors/report/report.hpp"

namespace visors::report {
namespace {

constexpr int kExitBadInput = 2;

}  // namespace

int run_report_command(const std::string& run_dir) {
  std::error_code ec;
  if (!std::filesystem::is_directory(run_dir, ec)) {
    fmt::print(stderr, "visors report: run directory '{}' does not exist or is not a directory\n", run_dir);
    return kExitBadInput;
  }
  const auto written = write_report(run_dir);
  if (!written) {
    fmt::print(stderr, "visors report: {}\n", written.error().describe());
    return kExitBadInput;
  }
  fmt::print("{}\n", written.value().string());
  return 0;
}

}  // namespace visors::report
