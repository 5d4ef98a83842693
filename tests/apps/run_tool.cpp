#include "apps/run_tool.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace visors::test {
namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ToolRun run_command(const std::string& args, const std::string& input) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("visors_tool_" + std::to_string(::getpid()) + "_" +
                    std::to_string(reinterpret_cast<std::uintptr_t>(&input)));
  std::filesystem::create_directories(dir);
  const auto in_path = dir / "in.json";
  const auto out_path = dir / "out.txt";
  const auto err_path = dir / "err.txt";
  std::ofstream(in_path) << input;
  const std::string command = std::string("'") + VISORS_BINARY + "' " + args + " < '" +
                              in_path.string() + "' > '" + out_path.string() + "' 2> '" +
                              err_path.string() + "'";
  const int status = std::system(command.c_str());
  ToolRun run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.out = slurp(out_path);
  run.err = slurp(err_path);
  std::filesystem::remove_all(dir);
  return run;
}

}  // namespace

ToolRun run_tool(const std::string& name, const std::string& input) {
  return run_command("tool " + name, input);
}

ToolRun run_visors(const std::string& args) { return run_command(args, ""); }

}  // namespace visors::test
