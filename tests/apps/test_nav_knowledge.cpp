// What `visors nav`'s filters know, end to end on a 400 s `visors gnss-sim` run of the default
// scenario (white receiver), replayed on copies of the run directory with one file changed:
// - the attitude: the filters take the ADCS's reports (attitude_reported.csv), truth.csv's
//   quaternions only for scoring: changing truth.csv's quaternions leaves every estimate the
//   same and changes the scores; giving the filters the truth as the report changes the estimates;
// - the broadcast data sets: each filter has a set only from the epoch its own receiver decoded it
//   (ephemeris_decoded.csv): a set the DSC decodes late is in none of the DSC filter's fixes before
//   then, and in the OSC filter's (its own receiver decoded it at the start);
// - the settings: the truth receiver's noise in scenario.toml leaves every estimate the same, the
//   [flight] antenna the filters are told changes them;
// - a run without those files (gnss-sim before them) is refused naming the file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gnss/gnss_test_data.hpp"
#include "run_tool.hpp"
#include "support/csv_table.hpp"
#include "support/temp_file.hpp"
#include "support/white_receiver.hpp"

namespace visors::test {
namespace {

bool have_navigation_file() { return have_gnss_data("NYA100NOR_S_20241280000_01D_GN.rnx"); }

// The default gnss-sim scenario cut to 400 s, white receiver (the filter's figures assume it).
std::string short_scenario(const std::filesystem::path& dir) {
  std::string text = file_text(std::filesystem::path(VISORS_SOURCE_DIR) / "data/scenarios/gnss_sim.toml");
  const std::string key = "duration_s = 5700.0";
  const auto at = text.find(key);
  EXPECT_NE(at, std::string::npos);
  text.replace(at, key.size(), "duration_s = 400.0");
  whiten_shipped_receiver(text);
  text += "\n[nav]\nelevation_weighting = false\n";
  const auto path = dir / "short.toml";
  std::ofstream(path) << text;
  return path.string();
}

// A copy of the run directory `run` as `name`, its file `file` rewritten by `change`.
template <class Change>
std::filesystem::path changed_copy(const std::filesystem::path& run, const std::string& name, const std::string& file,
                                   Change change) {
  const auto copy = run.parent_path() / name;
  std::filesystem::copy(run, copy, std::filesystem::copy_options::recursive);
  CsvTable t = read_csv_table(copy / file);
  change(t);
  write_csv_table(copy / file, t);
  return copy;
}

// A copy of the run directory `run` as `name`, in its scenario.toml the line starting with `key`
// (a resolved scenario writes each key once) replaced by `line`.
std::filesystem::path scenario_copy(const std::filesystem::path& run, const std::string& name, const std::string& key,
                                    const std::string& line) {
  const auto copy = run.parent_path() / name;
  std::filesystem::copy(run, copy, std::filesystem::copy_options::recursive);
  std::string text = file_text(copy / "scenario.toml");
  const auto at = text.find("\n" + key);
  EXPECT_NE(at, std::string::npos) << key;
  if (at != std::string::npos) text.replace(at + 1, text.find('\n', at + 1) - at - 1, line);
  std::ofstream(copy / "scenario.toml") << text;
  return copy;
}

// The estimated states of nav_<craft>.csv (both spacecraft's centres of mass and antennas): the
// columns from dsc_com_x_m on, per row.
std::vector<std::string> estimates(const CsvTable& nav) {
  std::vector<std::string> out;
  const std::size_t first = nav.column("dsc_com_x_m");
  for (const auto& row : nav.rows) {
    std::string s = row[0];
    for (std::size_t i = first; i < row.size(); ++i) s += "," + row[i];
    out.push_back(s);
  }
  return out;
}

// The DSC's late data set: a PRN of the DSC filter's fixes in its first 100 s of fixing whose
// first data set the DSC's receiver decoded at the start and which is still in its fixes at the
// end (so that it is fixed again after its late decoding).
int late_prn(const std::filesystem::path& nav, const CsvTable& decoded) {
  const CsvTable fixes = read_csv_table(nav / "fixes_dsc.csv");
  const double first_s = std::stod(fixes.rows.at(0)[0]);
  std::set<int> early, late;
  for (const auto& row : fixes.rows) {
    const double t_s = std::stod(row[0]);
    if (t_s < first_s + 100.0) early.insert(std::stoi(row[fixes.column("prn")]));
    if (t_s > 350.0) late.insert(std::stoi(row[fixes.column("prn")]));
  }
  for (const auto& row : decoded.rows) {
    const int prn = std::stoi(row[decoded.column("prn")]);
    if (row[decoded.column("spacecraft")] == "dsc" && std::stod(row[0]) < 60.0 && early.count(prn) && late.count(prn)) return prn;
  }
  return 0;
}

constexpr double kLateDecodingS = 200.0;

class NavKnowledge : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_navigation_file()) return;
    dir = new TempDir();
    const auto run = dir->path() / "run";
    const auto sim = run_visors("gnss-sim " + short_scenario(dir->path()) + " --out " + run.string());
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    replay(run, "nav");
    // truth.csv's attitudes all replaced by the identity: the filters must not see it.
    replay(changed_copy(run, "truth_changed", "truth.csv",
                        [](CsvTable& t) {
                          for (auto& row : t.rows) {
                            row[t.column("qw_body_to_gcrf")] = "1.0";
                            for (const char* q : {"qx_body_to_gcrf", "qy_body_to_gcrf", "qz_body_to_gcrf"}) row[t.column(q)] = "0.0";
                          }
                        }),
           "nav_truth_changed");
    // The truth's attitudes given as the ADCS's reports: the filters must see it.
    const CsvTable truth = read_csv_table(run / "truth.csv");
    replay(changed_copy(run, "truth_reported", "attitude_reported.csv",
                        [&truth](CsvTable& t) {
                          for (std::size_t i = 0; i < t.rows.size(); ++i) {
                            for (const char* q : {"qw_body_to_gcrf", "qx_body_to_gcrf", "qy_body_to_gcrf", "qz_body_to_gcrf"}) {
                              t.rows[i][t.column(q)] = truth.rows.at(i)[truth.column(q)];
                            }
                          }
                        }),
           "nav_truth_reported");
    // The truth receiver's noise changed in the scenario: the filters' weights are the flight's.
    replay(scenario_copy(run, "receiver_changed", "phase_sigma_m = ", "phase_sigma_m = 0.01"), "nav_receiver_changed");
    // The antenna the flight software is told, changed: the filters must see it.
    replay(scenario_copy(run, "flight_changed", "antenna_pco_m = ", "antenna_pco_m = 0.0954"), "nav_flight_changed");
    // One data set decoded by the DSC's receiver at 200 s instead of the start.
    prn = late_prn(dir->path() / "nav", read_csv_table(run / "ephemeris_decoded.csv"));
    replay(changed_copy(run, "late", "ephemeris_decoded.csv",
                        [](CsvTable& t) {
                          for (auto& row : t.rows) {
                            if (row[t.column("spacecraft")] == "dsc" && std::stoi(row[t.column("prn")]) == prn && std::stod(row[0]) < 60.0) {
                              row[0] = std::to_string(kLateDecodingS);
                            }
                          }
                        }),
           "nav_late");
  }
  static void replay(const std::filesystem::path& run, const std::string& out) {
    const auto nav = run_visors("nav " + run.string() + " --out " + (dir->path() / out).string());
    EXPECT_EQ(nav.exit_code, 0) << out << ": " << nav.err;
  }
  static void TearDownTestSuite() { delete dir; }
  void SetUp() override {
    if (!have_navigation_file()) GTEST_FAIL() << "a data file of data/ not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    ASSERT_NE(prn, 0) << "no PRN of the DSC's early and late fixes decoded at the start";
  }
  static CsvTable nav(const std::string& out, const std::string& file) { return read_csv_table(dir->path() / out / file); }
  static TempDir* dir;
  static int prn;
};
TempDir* NavKnowledge::dir = nullptr;
int NavKnowledge::prn = 0;

// truth.csv's attitudes changed: every estimate of both filters byte for byte the same, the
// scores not (the antennas' relative error is against the true phase centres, r + q_true l).
TEST_F(NavKnowledge, TruthAttitudeIsForScoringOnly) {
  for (const char* craft : {"dsc", "osc"}) {
    const std::string file = std::string("nav_") + craft + ".csv";
    const CsvTable original = nav("nav", file), changed = nav("nav_truth_changed", file);
    ASSERT_GT(original.rows.size(), 300U) << craft;
    EXPECT_EQ(estimates(changed), estimates(original)) << craft;
    int scores_differ = 0;
    const std::size_t column = original.column("rel_antenna_r_m");
    for (std::size_t i = 0; i < original.rows.size() && i < changed.rows.size(); ++i) {
      scores_differ += original.rows[i][column] != changed.rows[i][column] ? 1 : 0;
    }
    EXPECT_GT(scores_differ, 300) << craft << ": precondition, the truth's attitude is what scores";
  }
}

// The truth receiver's phase noise changed five-fold in scenario.toml: every estimate the same
// (the filters' sigmas are the [nav] flight settings, never the truth receiver's).
TEST_F(NavKnowledge, TruthReceiverNoiseDoesNotTuneTheFilters) {
  for (const char* craft : {"dsc", "osc"}) {
    const std::string file = std::string("nav_") + craft + ".csv";
    EXPECT_EQ(estimates(nav("nav_receiver_changed", file)), estimates(nav("nav", file))) << craft;
  }
}

// The [flight] antenna the filters are told moved by 1 cm: the estimates change.
TEST_F(NavKnowledge, FiltersTakeTheToldAntenna) {
  for (const char* craft : {"dsc", "osc"}) {
    const std::string file = std::string("nav_") + craft + ".csv";
    EXPECT_NE(estimates(nav("nav_flight_changed", file)), estimates(nav("nav", file))) << craft;
  }
}

// The truth given as the reports: the estimates change (the filters read attitude_reported.csv).
TEST_F(NavKnowledge, FiltersTakeTheReportedAttitude) {
  for (const char* craft : {"dsc", "osc"}) {
    const std::string file = std::string("nav_") + craft + ".csv";
    EXPECT_NE(estimates(nav("nav_truth_reported", file)), estimates(nav("nav", file))) << craft;
  }
}

// Each filter's cold start needs its receiver's decoded sets: not before the earliest (18 s after
// a lock at a frame start; the run starts at one) plus the 10 s between the two point solutions.
TEST_F(NavKnowledge, ColdStartWaitsForTheDecodedDataSets) {
  const auto summary = nlohmann::json::parse(file_text(dir->path() / "nav" / "summary.json"));
  const CsvTable decoded = read_csv_table(dir->path() / "run" / "ephemeris_decoded.csv");
  double first_s = 1e9;
  for (const auto& row : decoded.rows) first_s = std::min(first_s, std::stod(row[0]));
  EXPECT_EQ(first_s, 18.0);
  for (int k = 0; k < 2; ++k) EXPECT_GE(summary["filters"][k]["start_s"].get<double>(), first_s + 10.0) << k;
}

// The DSC's receiver decoded `prn`'s set at 200 s: no fix of the DSC's filter holds it before
// then; some after; the OSC's filter, whose receiver decoded it at the start, fixes it before.
TEST_F(NavKnowledge, DataSetIsNotUsedBeforeItsReceiverDecodedIt) {
  const auto uses = [](const CsvTable& fixes, double from_s, double to_s) {
    int n = 0;
    for (const auto& row : fixes.rows) {
      const double t_s = std::stod(row[0]);
      const bool with = std::stoi(row[fixes.column("prn")]) == prn || std::stoi(row[fixes.column("reference_prn")]) == prn;
      n += with && t_s >= from_s && t_s < to_s ? 1 : 0;
    }
    return n;
  };
  const CsvTable dsc = nav("nav_late", "fixes_dsc.csv"), osc = nav("nav_late", "fixes_osc.csv");
  ASSERT_GT(dsc.rows.size(), 100U);
  std::printf("G%02d decoded by the DSC at %.0f s: in %d DSC fix rows before, %d after; in %d OSC fix rows before\n", prn,
              kLateDecodingS, uses(dsc, 0.0, kLateDecodingS), uses(dsc, kLateDecodingS, 1e9), uses(osc, 0.0, kLateDecodingS));
  EXPECT_EQ(uses(dsc, 0.0, kLateDecodingS), 0) << "G" << prn;
  EXPECT_GT(uses(dsc, kLateDecodingS, 1e9), 0) << "G" << prn;
  EXPECT_GT(uses(osc, 0.0, kLateDecodingS), 0) << "G" << prn;
  EXPECT_GT(uses(nav("nav", "fixes_dsc.csv"), 0.0, kLateDecodingS), 0) << "G" << prn << ": precondition";
}

// A run without attitude_reported.csv or ephemeris_decoded.csv (gnss-sim before them) exits 2
// naming the file: visors nav does not fall back on the truth's attitude or on every set from its
// first broadcast.
TEST_F(NavKnowledge, OlderRunsAreRefusedNamingTheFile) {
  for (const char* file : {"attitude_reported.csv", "ephemeris_decoded.csv"}) {
    const auto copy = dir->path() / (std::string("without_") + file);
    std::filesystem::copy(dir->path() / "run", copy, std::filesystem::copy_options::recursive);
    std::filesystem::remove(copy / file);
    const auto run = run_visors("nav " + copy.string() + " --out " + (dir->path() / "never").string());
    EXPECT_EQ(run.exit_code, 2) << file;
    EXPECT_NE(run.err.find(file), std::string::npos) << run.err;
  }
}

}  // namespace
}  // namespace visors::test
