#include "apps/preview/preview_command.hpp"

#include <cstdio>
#include <fstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "visors/core/files/data_path.hpp"
#include "apps/preview/formation_preview.hpp"
#include "apps/preview/preview_scenario.hpp"

namespace visors::preview {
namespace {

constexpr int kExitBadInput = 2;

nlohmann::json to_json(const PreviewSummary& s) {
  nlohmann::json j;
  j["chief_period_s"] = s.chief_period_s;
  j["beta_angle_deg"] = s.beta_angle_deg;
  j["eop"] = s.eop_note;
  for (const auto& f : s.formations) {
    j["formations"].push_back({{"name", f.name},
                               {"csv", f.csv.string()},
                               {"min_separation_m", f.min_separation_m},
                               {"max_separation_m", f.max_separation_m},
                               {"min_rn_separation_m", f.min_rn_separation_m},
                               {"max_model_error_m", f.max_model_error_m},
                               {"drift_along_track_m_per_orbit", f.drift_along_track_m_per_orbit},
                               {"best_sun_alignment_deg", f.best_sun_alignment_deg},
                               {"best_sun_alignment_time_s", f.best_sun_alignment_time_s},
                               {"separation_at_best_alignment_m", f.separation_at_best_alignment_m}});
  }
  return j;
}

void print_report(const PreviewSummary& s, const std::string& out_dir) {
  fmt::print("chief period {:.2f} s, beta angle at epoch {:.2f} deg; {}\n", s.chief_period_s,
             s.beta_angle_deg, s.eop_note);
  fmt::print("{:<12} {:>9} {:>9} {:>9} {:>11} {:>12} {:>10} {:>10}\n", "formation", "min sep",
             "max sep", "min RN", "model err", "drift", "best Sun", "sep there");
  fmt::print("{:<12} {:>9} {:>9} {:>9} {:>11} {:>12} {:>10} {:>10}\n", "", "[m]", "[m]", "[m]",
             "[mm]", "[m/orbit]", "[deg]", "[m]");
  for (const auto& f : s.formations) {
    fmt::print("{:<12} {:>9.3f} {:>9.3f} {:>9.3f} {:>11.2f} {:>12.3f} {:>10.3f} {:>10.3f}\n",
               f.name, f.min_separation_m, f.max_separation_m, f.min_rn_separation_m,
               1e3 * f.max_model_error_m, f.drift_along_track_m_per_orbit,
               f.best_sun_alignment_deg, f.separation_at_best_alignment_m);
  }
  fmt::print("ephemerides and summary.json written to {}\n", out_dir);
}

}  // namespace

int run_preview_command(const std::string& scenario_path, const std::string& out_dir) {
  const auto path = core::files::find_data_file(scenario_path);
  if (!path) {
    fmt::print(stderr, "visors preview: scenario: '{}' not found (nor in VISORS_DATA_PATH or data/)\n",
               scenario_path);
    return kExitBadInput;
  }
  auto scenario = load_preview_scenario(*path);
  if (!scenario.ok()) {
    fmt::print(stderr, "visors preview: {}: {}\n", path->string(), scenario.error().describe());
    return kExitBadInput;
  }
  auto summary = run_formation_preview(scenario.value(), out_dir);
  if (!summary.ok()) {
    fmt::print(stderr, "visors preview: {}\n", summary.error().describe());
    return kExitBadInput;
  }
  std::ofstream(std::filesystem::path(out_dir) / "summary.json") << to_json(summary.value()).dump(2)
                                                                 << '\n';
  print_report(summary.value(), out_dir);
  return 0;
}

}  // namespace visors::preview
