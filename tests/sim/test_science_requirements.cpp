// System test of the science phase against the observation requirements of
// Guffanti et al., AAS 23-149, 2023, sec. 2 (docs/requirements.md#science-alignment-requirements):
// 40 observation attempts from the paper's science orbit, in four 10-attempt runs with the first
// four seeds (ideal navigation, every other random model on: propulsion execution errors, payload
// geometry errors, crosslink), about 30 s in all.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

#include "visors/sim/campaign_simulation.hpp"

namespace {

using visors::sim::campaign_from_toml;
using visors::sim::run_campaign;

// Guffanti et al., AAS 23-149, 2023, sec. 2: the three alignment requirements over each 10 s
// observation.
constexpr double kLateralErrorMax_m = 0.018;         // photon-sieve centre off the line of sight
constexpr double kLateralVelocityMax_mps = 0.2e-3;   // relative velocity across the line of sight
constexpr double kFocusErrorMax_m = 0.015;           // separation off the nominal 40 m
// The same paper, sec. 2: one success in five attempts (20 %) declares mission success.
constexpr double kRequiredSuccessRate = 0.20;

constexpr int kSeeds = 4;
constexpr int kAttemptsPerRun = 10;

std::string scenario(int seed) {
  return "name = \"science_requirements\"\nseed = " + std::to_string(seed) + R"(
[formation]
initial_roe_m = [0.015, 35.09, -34.77, 5.10, -19.09, 2.81]
[campaign]
standby_s = 60.0
observations = 10
tail_s = 60.0
[time]
max_duration_s = 70000.0
[navigation]
mode = "ideal"
)";
}

struct Pooled {
  int attempts = 0;
  int successes = 0;
  int flags_disagreeing = 0;  // success flags that disagree with the three requirements
  int safety_violations = 0;
  double min_rn_m = 1e9;
  nlohmann::json requirements;
};

Pooled run_all() {
  Pooled p;
  for (int seed = 1; seed <= kSeeds; ++seed) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("visors_science_" + std::to_string(::getpid()) + "_" + std::to_string(seed));
    const auto result = run_campaign(campaign_from_toml(scenario(seed)).value(), dir);
    std::filesystem::remove_all(dir);
    if (!result.ok()) {
      ADD_FAILURE() << "seed " << seed << ": " << result.error().describe();
      continue;
    }
    const nlohmann::json& s = result->summary;
    for (const auto& o : s["observations"]) {
      const bool meets = o["lateral_error_m"].get<double>() <= kLateralErrorMax_m &&
                         o["lateral_velocity_mps"].get<double>() <= kLateralVelocityMax_mps &&
                         o["focus_error_m"].get<double>() <= kFocusErrorMax_m;
      ++p.attempts;
      p.successes += meets ? 1 : 0;
      p.flags_disagreeing += meets != o["success"].get<bool>() ? 1 : 0;
    }
    p.safety_violations += s["safety_violations"].get<int>();
    p.min_rn_m = std::min(p.min_rn_m, s["min_separation_rn_m"].get<double>());
    p.requirements = s["requirements"];
  }
  return p;
}

TEST(ScienceRequirements, FortyAttemptsMeetThePapersSuccessCriterion) {
  const Pooled p = run_all();
  // Every commanded attempt is made.
  EXPECT_EQ(p.attempts, kSeeds * kAttemptsPerRun);
  // The simulator judges with the paper's numbers.
  EXPECT_DOUBLE_EQ(p.requirements["lateral_error_m"].get<double>(), kLateralErrorMax_m);
  EXPECT_DOUBLE_EQ(p.requirements["lateral_velocity_mps"].get<double>(), kLateralVelocityMax_mps);
  EXPECT_DOUBLE_EQ(p.requirements["focus_error_m"].get<double>(), kFocusErrorMax_m);
  // Each attempt's success flag is exactly the three requirements on its worst-case metrics.
  EXPECT_EQ(p.flags_disagreeing, 0);
  // The paper's mission-success criterion over the pooled attempts (measured 10 of 40 = 25 %
  // with these seeds, 2026-11: 1, 2, 3, 4 of 10; the paper's Monte Carlo reports > 20 % with
  // the centre of mass known to better than 1 cm).
  EXPECT_GE(static_cast<double>(p.successes) / p.attempts, kRequiredSuccessRate)
      << p.successes << " of " << p.attempts;
  // Passive safety all along (paper: the science orbit's e/i separation, ~19 m in RN; safety
  // epsilon 5 m).
  EXPECT_EQ(p.safety_violations, 0);
  EXPECT_GT(p.min_rn_m, 5.0);
}

}  // namespace
