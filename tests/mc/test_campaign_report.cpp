// mc/campaign_report from a store filled with made-up runs whose figures are known: the value
// table counts each value's attempts and successes, failed runs are listed with their reason,
// and each sweep gets its two figures.
#include "visors/mc/campaign_report.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "visors/mc/run_plan.hpp"
#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

nlohmann::json summary_with(std::initializer_list<std::pair<double, bool>> attempts) {
  nlohmann::json observations = nlohmann::json::array();
  int index = 1;
  for (const auto& [lateral, success] : attempts) {
    observations.push_back({{"index", index++}, {"lateral_error_m", lateral}, {"lateral_x_m", lateral}, {"lateral_y_m", 0.0},
                            {"focus_signed_m", 0.0}, {"success", success}});
  }
  return {{"observations", observations},
          {"requirements", {{"lateral_error_m", 0.018}}},
          {"delta_v_mps", {{"osc", {{"total", 1.0}}}, {"dsc", {{"total", 0.0}}}}}};
}

// Runs 0, 1: value 0.5 (3 of 4 attempts succeed); run 2: value 1.0, 0 of 2; run 3 failed.
std::vector<RunRecord> four_runs() {
  return {{0, true, 1.0, "", summary_with({{0.005, true}, {0.010, true}})},
          {1, true, 1.0, "", summary_with({{0.004, true}, {0.030, false}})},
          {2, true, 1.0, "", summary_with({{0.025, false}, {0.040, false}})},
          {3, false, 1.0, "crashed: signal 11 (Segmentation fault)", nullptr}};
}

// The report written from made-up runs; the text of `file` in its folder.
std::string report_text(const std::string& file = "report.html", const std::vector<RunRecord>& records = four_runs()) {
  const auto dir = test::campaign_folder("report");
  const Campaign c = load_campaign((dir / "campaign.toml").string()).value();
  auto store = ResultsStore::open(dir / "db.sqlite").value();
  EXPECT_TRUE(store.record_campaign(c, "", {}).ok());
  for (const RunRecord& r : records) EXPECT_TRUE(store.store(run_spec(c, r.run), r).ok());
  EXPECT_TRUE(write_campaign_report(store, dir).ok());
  std::stringstream text;
  text << std::ifstream(dir / file).rdbuf();
  std::filesystem::remove_all(dir);
  return text.str();
}

StoredRun stored(const std::string& value_text, nlohmann::json summary) {
  StoredRun r;
  r.sweep_key = "propulsion.magnitude_sigma";
  r.sweep_value_text = value_text;
  r.ok = !summary.is_null();
  r.summary = std::move(summary);
  return r;
}

// The terminal's summary keeps the campaign's order: "2.5" before "10.0" (text order would swap
// them), and a failed run adds no attempt.
TEST(CampaignReport, SuccessByValueKeepsTheCampaignsOrder) {
  const auto values = success_by_value({stored("2.5", summary_with({{0.005, true}})), stored("10.0", summary_with({{0.03, false}})),
                                        stored("2.5", nullptr)});
  ASSERT_EQ(values.size(), 2U);
  EXPECT_EQ(values[0].value, "2.5");
}

TEST(CampaignReport, SuccessByValueCountsAttemptsAndSuccesses) {
  const auto values = success_by_value({stored("2.5", summary_with({{0.005, true}, {0.03, false}})), stored("2.5", nullptr)});
  ASSERT_EQ(values.size(), 1U);
  EXPECT_EQ(values[0].successes, 1);
  EXPECT_EQ(values[0].attempts, 2);
}

TEST(CampaignReport, CountsEachValuesSuccesses) {
  EXPECT_NE(report_text().find("<td>0.5</td><td>2</td><td>0</td><td>4</td><td>75 %</td>"), std::string::npos);
}

TEST(CampaignReport, CountsAFailedRunAgainstItsValue) {
  EXPECT_NE(report_text().find("<td>1.0</td><td>2</td><td>1</td><td>2</td><td>0 %</td>"), std::string::npos);
}

TEST(CampaignReport, ListsTheFailedRunWithItsReason) {
  EXPECT_NE(report_text().find("<td>3</td><td>crosslink.delay_s = 1.0</td>"), std::string::npos);
}

TEST(CampaignReport, DrawsTheSensitivityAndDispersionFiguresOfTheSweep) {
  const std::string text = report_text();
  EXPECT_TRUE(text.find("id=\"sensitivity0\"") != std::string::npos && text.find("id=\"dispersion0\"") != std::string::npos);
}

// A 0.9 m outlier among millimetres: the axis ends at 2.5x the 18 mm requirement (45 mm) and the
// title says that one outlier lies above it.
TEST(CampaignReport, CountsTheOutliersAboveTheWhiskerAxis) {
  const std::vector<RunRecord> runs = {
      {0, true, 1.0, "", summary_with({{0.005, true}, {0.006, true}, {0.007, true}, {0.008, true}, {0.009, true}, {0.9, false}})}};
  EXPECT_NE(report_text("sensitivity_0.svg", runs).find("(1 outlier above the axis)"), std::string::npos);
}

// The sweep's sensitivity figure alone, with the stylesheet inside (it renders without the page).
TEST(CampaignReport, WritesTheSensitivityFigureAsAnImageOfItsOwn) {
  const std::string svg = report_text("sensitivity_0.svg");
  EXPECT_TRUE(svg.find("id=\"sensitivity0\"") != std::string::npos && svg.find("<style>") != std::string::npos);
}

}  // namespace
}  // namespace visors::mc
