#pragma once
// A tiny campaign for the tests of src/visors/mc: a base scenario of 300 s of standby with ideal
// navigation (a fraction of a second per run), a swept key and a dispersion, written to a fresh
// folder.

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "visors/mc/sqlite_database.hpp"

namespace visors::mc::test {

inline constexpr const char* kBaseScenario = R"(
[campaign]
standby_s = 0.0
observations = 0
tail_s = 300.0
[navigation]
mode = "ideal"
)";

inline constexpr const char* kTinyCampaign = R"(
name = "tiny"
scenario = "base.toml"
seed = 7
runs_per_value = 2
time_limit_s = 120.0
[dispersions]
"propulsion.isp_s" = { normal = { mean = 44.0, sigma = 2.0 } }
[[sweep]]
key = "crosslink.delay_s"
values = [0.5, 1.0]
)";

/// A fresh folder under the temporary directory holding base.toml and campaign.toml (`campaign`).
inline std::filesystem::path campaign_folder(const std::string& name, const std::string& campaign = kTinyCampaign) {
  const auto dir = std::filesystem::temp_directory_path() / ("visors_mc_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "base.toml") << kBaseScenario;
  std::ofstream(dir / "campaign.toml") << campaign;
  return dir;
}

/// The host-independent content of a results database, as text (every table but the runs' wall
/// times, timings and finish times), for comparisons.
inline std::string database_content(const std::filesystem::path& path) {
  auto db = SqlDatabase::open(path).value();
  std::string out;
  for (const char* sql : {"SELECT run, sweep_key, sweep_value_text, replicate, seed, parameters, status, error FROM runs ORDER BY run",
                          "SELECT * FROM observations ORDER BY run, attempt", "SELECT * FROM summaries ORDER BY run",
                          "SELECT name, file_text, scenario_text, base_scenario, total_runs FROM campaign"}) {
    auto s = db.prepare(sql).value();
    while (s.step().value()) {
      for (int c = 0; c < 11; ++c) out += s.text(c) + "|";
      out += "\n";
    }
  }
  return out;
}

}  // namespace visors::mc::test
