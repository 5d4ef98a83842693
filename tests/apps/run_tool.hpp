#pragma once
// Runs the real `visors` binary with a JSON document on stdin and captures stdout, stderr and
// the exit code, for the end-to-end tool tests.

#include <string>

#include <nlohmann/json.hpp>

namespace visors::test {

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
  [[nodiscard]] nlohmann::json json() const { return nlohmann::json::parse(out); }
};

/// `visors tool NAME` with `input` on stdin.
ToolRun run_tool(const std::string& name, const std::string& input);

/// `visors ARGS...` (space-separated, no shell quoting needed by the callers), empty stdin.
ToolRun run_visors(const std::string& args);

}  // namespace visors::test
