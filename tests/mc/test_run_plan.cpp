// mc/run_plan: run order, seeds (splitmix64 against its published reference), common random
// numbers, dispersion draws and the scenario of a run.
#include "visors/mc/run_plan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

// `top` holds root keys (before the file's tables), `tables` more tables (after them).
Campaign tiny(const std::string& top = "", const std::string& tables = "") {
  return campaign_from_toml(top + test::kTinyCampaign + tables, {}, std::string(test::kBaseScenario)).value();
}

Campaign unswept(const std::string& text) { return campaign_from_toml(text, {}, std::string(test::kBaseScenario)).value(); }

// Vigna's splitmix64.c seeded with 0: first outputs 0xe220a8397b1dcdaf, 0x6e789e6aa1b965f4.
TEST(RunPlan, SplitMix64MatchesTheReferenceFirstOutput) { EXPECT_EQ(splitmix64(0), 0xe220a8397b1dcdafULL); }

TEST(RunPlan, SplitMix64MatchesTheReferenceSecondOutput) {
  EXPECT_EQ(splitmix64(0x9E3779B97F4A7C15ULL), 0x6e789e6aa1b965f4ULL);
}

TEST(RunPlan, RunsAreSweepValueReplicateInOrder) {
  const RunSpec r = run_spec(tiny(), 3);  // 2 values x 2 replicates: run 3 is value 1, replicate 1
  EXPECT_EQ(r.value * 10 + r.replicate, 11);
}

TEST(RunPlan, TheSweptValueIsTheFirstParameter) {
  const RunSpec r = run_spec(tiny(), 2);
  EXPECT_EQ(to_text(r.parameters.front().second), "1.0");
}

TEST(RunPlan, PairedRunsShareTheirReplicatesSeed) { EXPECT_EQ(run_spec(tiny(), 0).seed, run_spec(tiny(), 2).seed); }

TEST(RunPlan, UnpairedRunsHaveTheirOwnSeed) {
  const Campaign c = tiny("paired = false\n");
  EXPECT_NE(run_spec(c, 0).seed, run_spec(c, 2).seed);
}

TEST(RunPlan, SeedsFitATomlInteger) {
  for (std::int64_t i = 0; i < 4; ++i) EXPECT_LE(run_spec(tiny(), i).seed, 0x7FFF'FFFF'FFFF'FFFFULL);
}

TEST(RunPlan, ARunIsTheSameWhenPlannedAgain) {
  EXPECT_EQ(to_text(run_spec(tiny(), 1).parameters.back().second), to_text(run_spec(tiny(), 1).parameters.back().second));
}

// The normal draws of 4000 runs: mean 44 and sigma 2 within 5 standard errors.
struct Moments {
  double mean = 0.0, std = 0.0;
};
Moments isp_moments() {
  const Campaign c = unswept("runs = 4000\npaired = false\n[dispersions]\n\"propulsion.isp_s\" = { normal = { mean = 44.0, sigma = 2.0 } }\n");
  double sum = 0.0, sum2 = 0.0;
  for (std::int64_t i = 0; i < c.total_runs(); ++i) {
    const double v = to_number(run_spec(c, i).parameters.back().second);
    sum += v;
    sum2 += v * v;
  }
  const double n = static_cast<double>(c.total_runs());
  return {sum / n, std::sqrt(sum2 / n - (sum / n) * (sum / n))};
}

TEST(RunPlan, NormalDrawsHaveTheirMean) { EXPECT_NEAR(isp_moments().mean, 44.0, 5.0 * 2.0 / std::sqrt(4000.0)); }

TEST(RunPlan, NormalDrawsHaveTheirSigma) { EXPECT_NEAR(isp_moments().std, 2.0, 5.0 * 2.0 / std::sqrt(8000.0)); }

TEST(RunPlan, UniformDrawsStayInTheirInterval) {
  const Campaign c = unswept("runs = 500\npaired = false\n[dispersions]\n\"crosslink.delay_s\" = { uniform = { min = 0.2, max = 0.4 } }\n");
  double lo = 1.0, hi = 0.0;
  for (std::int64_t i = 0; i < c.total_runs(); ++i) {
    const double v = to_number(run_spec(c, i).parameters.back().second);
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  EXPECT_TRUE(lo >= 0.2 && hi < 0.4 && hi - lo > 0.19);
}

TEST(RunPlan, ChoiceDrawsReachEveryChoice) {
  const Campaign c = unswept("runs = 200\npaired = false\n[dispersions]\n\"navigation.mode\" = { choice = [\"ideal\", \"cdgps\"] }\n");
  int ideal = 0;
  for (std::int64_t i = 0; i < c.total_runs(); ++i) ideal += to_text(run_spec(c, i).parameters.back().second) == "\"ideal\"";
  EXPECT_TRUE(ideal > 60 && ideal < 140);  // binomial(200, 1/2): 100 +/- 5.7 standard deviations
}

TEST(RunPlan, TheRunsScenarioHasItsSweptValue) {
  const Campaign c = tiny();
  EXPECT_EQ(scenario_for(c, run_spec(c, 2))->crosslink_delay_s, 1.0);
}

TEST(RunPlan, TheRunsScenarioHasItsDraw) {
  const Campaign c = tiny();
  const RunSpec r = run_spec(c, 1);
  EXPECT_EQ(scenario_for(c, r)->propulsion.isp_s, to_number(r.parameters.back().second));
}

TEST(RunPlan, TheRunsScenarioHasItsSeed) {
  const Campaign c = tiny();
  const RunSpec r = run_spec(c, 1);
  EXPECT_EQ(scenario_for(c, r)->seed, r.seed);
}

TEST(RunPlan, SetValuesReachTheBaseScenario) {
  const Campaign c = tiny("", "[set]\n\"campaign.tail_s\" = 123.0\n");
  EXPECT_EQ(base_scenario(c)->tail_s, 123.0);
}

}  // namespace
}  // namespace visors::mc
