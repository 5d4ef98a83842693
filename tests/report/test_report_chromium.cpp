// The report as a browser sees it: headless Chromium loads report.html from disk and dumps its
// DOM; every figure must be there and draw data. Skipped when `chromium` is not on PATH (Debian
// package `chromium`, installed by scripts/install-deps.sh).

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <unistd.h>

#include <gtest/gtest.h>

#include "visors/report/report.hpp"
#include "visors/report/report_figures.hpp"
#include "report_checks.hpp"
#include "synthetic_run.hpp"

namespace visors::report {
namespace {

std::optional<std::filesystem::path> find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream folders(path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const std::filesystem::path candidate = std::filesystem::path(folder) / name;
    if (!folder.empty() && ::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

// Standard output of `command`.
std::string run_capturing(const std::string& command) {
  std::string out;
  const std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) return out;
  std::array<char, 65536> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe.get())) > 0) out.append(buffer.data(), n);
  return out;
}

TEST(ReportInChromium, EveryFigureIsInTheDomAndDrawsData) {
  const auto chromium = find_on_path("chromium");
  if (!chromium) {
    GTEST_SKIP() << "chromium is not on PATH (Debian package 'chromium'); the headless browser check is skipped";
  }
  const test::SyntheticRun run({.orbits = 2.0});
  const auto report = write_report(run.dir());
  ASSERT_TRUE(report.ok()) << report.error().describe();
  // A throw-away profile per run: parallel test processes must not share Chromium's profile lock.
  // --no-sandbox: Chromium refuses to start as root with its sandbox (CI runs as root).
  const std::filesystem::path profile = run.dir() / "chromium-profile";
  const std::string command = "timeout 60 '" + chromium->string() +
                              "' --headless --no-sandbox --disable-gpu --no-first-run --user-data-dir='" +
                              profile.string() + "' --dump-dom 'file://" + report.value().string() + "' 2>/dev/null";
  const std::string dom = run_capturing(command);
  ASSERT_FALSE(dom.empty()) << "chromium printed no DOM: " << command;
  for (const char* id : kFigureIds) {
    const std::string svg = test::figure_svg(dom, id);
    ASSERT_FALSE(svg.empty()) << id << " is missing from the DOM Chromium built";
    EXPECT_TRUE(test::draws_data(svg)) << id << " draws no data in Chromium's DOM";
  }
}

}  // namespace
}  // namespace visors::report
