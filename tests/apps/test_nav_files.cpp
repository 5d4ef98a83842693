// `visors nav`'s figures recomputed from the files alone, as an outsider would (no library code:
// the RTN frame, the double differences and the windows are rebuilt here): a 10-minute
// `visors gnss-sim` run of the default scenario with data gaps in both receivers and a noisy phase
// (3 cm), replayed with an acceptance loose enough to fix wrong integers (so that the wrong-fix
// count checked is not zero). From nav_<craft>.csv's estimated states and truth.csv the relative
// errors the file reports; from fixes_<craft>.csv and channels_truth.csv the wrong fixes the
// summary counts; from nav_<craft>.csv's status and truth.csv's epochs the fix rate over all
// epochs, the data gaps counted as not fixed.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "gnss/gnss_test_data.hpp"
#include "run_tool.hpp"
#include "support/csv_table.hpp"
#include "support/temp_file.hpp"
#include "support/white_receiver.hpp"

namespace visors::test {
namespace {

bool have_navigation_file() { return have_gnss_data("NYA100NOR_S_20241280000_01D_GN.rnx"); }

// The default scenario, 600 s, 3 cm phase, each receiver's epochs lost in 10-s gaps (a gap starts
// at an epoch with probability 0.005: a few per receiver in 600 s for the default seed).
std::string gappy_scenario(const std::filesystem::path& dir) {
  std::string text = file_text(std::filesystem::path(VISORS_SOURCE_DIR) / "data/scenarios/gnss_sim.toml");
  replace_once(text, "duration_s = 5700.0", "duration_s = 600.0");
  replace_once(text, "phase_sigma_m = 0.002", "phase_sigma_m = 0.03");
  replace_once(text, "# data_gap_probability = 0.0", "data_gap_probability = 0.005");
  whiten_shipped_receiver(text);
  const auto path = dir / "gappy.toml";
  std::ofstream(path) << text;
  return path.string();
}

// The filter told the SD phase's noise (sqrt(2) x 3 cm), fixing from its first epoch whatever
// the success rate and the ratio, without partial fixes or hold: wrong fixes happen.
std::string loose_settings(const std::filesystem::path& dir) {
  const auto path = dir / "loose.toml";
  std::ofstream(path) << "[nav]\nelevation_weighting = false\nsdcp_sigma_m = 0.0424\nmin_float_s_before_fix = 0.0\nhold = false\n"
                         "[nav.acceptance]\nmin_success_rate = 0.01\nmin_ratio = 1.0\npartial = false\n";
  return path.string();
}

long long key_ms(double t_s) { return std::llround(1000.0 * t_s); }

// truth.csv: per epoch (ms) and spacecraft ("dsc", "osc") its row.
using TruthRows = std::map<long long, std::map<std::string, std::size_t>>;
TruthRows index_truth(const CsvTable& truth) {
  TruthRows out;
  for (std::size_t i = 0; i < truth.rows.size(); ++i) out[key_ms(truth.number(i, "t_s"))][truth.text(i, "spacecraft")] = i;
  return out;
}

// GCRF to the RTN frame of a state: R along r, N along r x v, T = N x R.
Eigen::Matrix3d gcrf_to_rtn(const Eigen::Vector3d& r, const Eigen::Vector3d& v) {
  const Eigen::Vector3d R = r.normalized(), N = r.cross(v).normalized();
  Eigen::Matrix3d m;
  m.row(0) = R.transpose();
  m.row(1) = N.cross(R).transpose();
  m.row(2) = N.transpose();
  return m;
}

class NavFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_navigation_file()) return;
    dir = new TempDir();
    const auto sim = run_visors("gnss-sim " + gappy_scenario(dir->path()) + " --out " + run().string());
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    const auto nav = run_visors("nav " + run().string() + " --out " + out().string() + " --settings " + loose_settings(dir->path()));
    ASSERT_EQ(nav.exit_code, 0) << nav.err;
    summary = nlohmann::json::parse(file_text(out() / "summary.json"));
  }
  static void TearDownTestSuite() { delete dir; }
  void SetUp() override {
    if (!have_navigation_file()) GTEST_FAIL() << "a data file of data/ not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    ASSERT_FALSE(summary.is_null());
  }
  static std::filesystem::path run() { return dir->path() / "run"; }
  static std::filesystem::path out() { return dir->path() / "nav"; }
  static const nlohmann::json& filter(int k) { return summary["filters"][k]; }
  static TempDir* dir;
  static nlohmann::json summary;
};
TempDir* NavFiles::dir = nullptr;
nlohmann::json NavFiles::summary;

const char* const kCrafts[2] = {"dsc", "osc"};

// The relative errors of each row (estimate minus truth, OSC minus DSC, the true DSC's RTN axes):
// centres of mass from the com columns, antennas from the antenna columns against the true
// phase centres r + q (phase centre - centre of mass), gnss-sim's summary.json body vectors.
// To 1.5 um and 2e-8 m/s: the columns' rounding (0.1 um, 1 nm/s; the errors' 1 um, 10 nm/s).
TEST_F(NavFiles, RelativeErrorsAreRecomputedFromTheEstimatedStatesAndTheTruth) {
  const CsvTable truth = read_csv_table(run() / "truth.csv");
  const TruthRows at = index_truth(truth);
  const nlohmann::json receivers = nlohmann::json::parse(file_text(run() / "summary.json"))["receivers"];
  const auto body = [&](const char* craft, const char* key) {
    const auto& v = receivers[craft][key];
    return Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  std::map<std::string, Eigen::Vector3d> true_lever_body_m;
  for (const char* craft : kCrafts) true_lever_body_m[craft] = body(craft, "phase_center_body_m") - body(craft, "center_of_mass_body_m");
  for (const char* filter_name : kCrafts) {
    const CsvTable nav = read_csv_table(out() / (std::string("nav_") + filter_name + ".csv"));
    ASSERT_GT(nav.rows.size(), 500U) << filter_name;
    double worst_m = 0.0, worst_antenna_m = 0.0, worst_mps = 0.0;
    for (std::size_t i = 0; i < nav.rows.size(); ++i) {
      const auto rows = at.at(key_ms(nav.number(i, "t_s")));
      std::map<std::string, Eigen::Vector3d> r, v, antenna;
      for (const char* craft : kCrafts) {
        const std::size_t row = rows.at(craft);
        r[craft] = truth.vector(row, "", "_gcrf_m");
        v[craft] = Eigen::Vector3d(truth.number(row, "vx_gcrf_mps"), truth.number(row, "vy_gcrf_mps"), truth.number(row, "vz_gcrf_mps"));
        const Eigen::Quaterniond q(truth.number(row, "qw_body_to_gcrf"), truth.number(row, "qx_body_to_gcrf"),
                                   truth.number(row, "qy_body_to_gcrf"), truth.number(row, "qz_body_to_gcrf"));
        antenna[craft] = r[craft] + q.normalized() * true_lever_body_m[craft];
      }
      const Eigen::Matrix3d rtn = gcrf_to_rtn(r["dsc"], v["dsc"]);
      const auto estimated = [&](const char* point, const char* suffix) {
        return Eigen::Vector3d(nav.vector(i, std::string("osc_") + point + "_", suffix) - nav.vector(i, std::string("dsc_") + point + "_", suffix));
      };
      const Eigen::Vector3d position = rtn * (estimated("com", "_m") - (r["osc"] - r["dsc"]));
      const Eigen::Vector3d antennas = rtn * (estimated("antenna", "_m") - (antenna["osc"] - antenna["dsc"]));
      const Eigen::Vector3d velocity = rtn * (Eigen::Vector3d(nav.number(i, "osc_com_vx_mps") - nav.number(i, "dsc_com_vx_mps"),
                                                              nav.number(i, "osc_com_vy_mps") - nav.number(i, "dsc_com_vy_mps"),
                                                              nav.number(i, "osc_com_vz_mps") - nav.number(i, "dsc_com_vz_mps")) -
                                              (v["osc"] - v["dsc"]));
      const Eigen::Vector3d written(nav.number(i, "rel_r_m"), nav.number(i, "rel_t_m"), nav.number(i, "rel_n_m"));
      const Eigen::Vector3d written_antenna(nav.number(i, "rel_antenna_r_m"), nav.number(i, "rel_antenna_t_m"), nav.number(i, "rel_antenna_n_m"));
      const Eigen::Vector3d written_velocity(nav.number(i, "rel_vr_mps"), nav.number(i, "rel_vt_mps"), nav.number(i, "rel_vn_mps"));
      worst_m = std::max(worst_m, (position - written).cwiseAbs().maxCoeff());
      worst_antenna_m = std::max(worst_antenna_m, (antennas - written_antenna).cwiseAbs().maxCoeff());
      worst_mps = std::max(worst_mps, (velocity - written_velocity).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst_m, 1.5e-6) << filter_name;
    EXPECT_LT(worst_antenna_m, 1.5e-6) << filter_name;
    EXPECT_LT(worst_mps, 2e-8) << filter_name;
  }
}

// channels_truth.csv: per epoch (ms), PRN and spacecraft (0 DSC, 1 OSC) the receiver's
// ambiguity plus phase offset [cycles]; their OSC-minus-DSC differences are the true single
// differences, whose double differences are integers (the phase offsets cancel).
using PhaseTruth = std::map<long long, std::map<int, std::array<double, 2>>>;
PhaseTruth read_phase_truth(const std::filesystem::path& path) {
  const CsvTable t = read_csv_table(path);
  PhaseTruth out;
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    auto& cycles = out[key_ms(t.number(i, "t_s"))][static_cast<int>(t.number(i, "prn"))];
    cycles[t.text(i, "spacecraft") == "dsc" ? 0 : 1] = t.number(i, "ambiguity_cycles") + t.number(i, "receiver_phase_cycles");
  }
  return out;
}

// An epoch's fix is wrong when any of its integers is off the truth's double difference by more
// than half a cycle; the count is the summary's, and the epochs are the nav file's wrong_fix rows.
// The fixes file holds one epoch per row "fixed" of the nav file.
TEST_F(NavFiles, WrongFixesAreRecomputedFromTheIntegersAndTheChannelTruth) {
  const PhaseTruth phase = read_phase_truth(run() / "channels_truth.csv");
  for (int k = 0; k < 2; ++k) {
    const std::string name = kCrafts[k];
    const CsvTable fixes = read_csv_table(out() / ("fixes_" + name + ".csv"));
    std::set<long long> fixed_epochs, wrong_epochs;
    for (std::size_t i = 0; i < fixes.rows.size(); ++i) {
      const long long t = key_ms(fixes.number(i, "t_s"));
      ASSERT_EQ(fixes.text(i, "signal"), "L1C");
      const auto& sats = phase.at(t);
      const auto sd = [&sats](int prn) { return sats.at(prn)[1] - sats.at(prn)[0]; };
      const double expected = sd(static_cast<int>(fixes.number(i, "prn"))) - sd(static_cast<int>(fixes.number(i, "reference_prn")));
      fixed_epochs.insert(t);
      if (std::abs(fixes.number(i, "integer_cycles") - expected) > 0.5) wrong_epochs.insert(t);
    }
    const CsvTable nav = read_csv_table(out() / ("nav_" + name + ".csv"));
    std::set<long long> nav_fixed, nav_wrong;
    for (std::size_t i = 0; i < nav.rows.size(); ++i) {
      if (nav.text(i, "status") == "fixed") nav_fixed.insert(key_ms(nav.number(i, "t_s")));
      if (nav.text(i, "wrong_fix") == "1") nav_wrong.insert(key_ms(nav.number(i, "t_s")));
    }
    EXPECT_GT(wrong_epochs.size(), 0U) << name << ": the loose acceptance should have fixed wrong integers";
    EXPECT_EQ(static_cast<int>(wrong_epochs.size()), filter(k)["after_first_fix"]["wrong_fix_epochs"].get<int>()) << name;
    EXPECT_EQ(wrong_epochs, nav_wrong) << name;
    EXPECT_EQ(fixed_epochs, nav_fixed) << name;
  }
}

// The fix rate over all epochs: the nav file's fixed rows from the first fix on over truth.csv's
// epochs after the cold start and from the first fix on, recorded or not; below the rate over the
// epochs present, the run having gaps.
TEST_F(NavFiles, FixRateOverAllEpochsCountsTheDataGapsAsNotFixed) {
  const CsvTable truth = read_csv_table(run() / "truth.csv");
  const TruthRows epochs = index_truth(truth);
  for (int k = 0; k < 2; ++k) {
    const std::string name = kCrafts[k];
    const double start_s = filter(k)["start_s"].get<double>();
    const double from_s = start_s + filter(k)["time_to_first_fix_s"].get<double>();
    ASSERT_GE(from_s, start_s) << name;
    const CsvTable nav = read_csv_table(out() / ("nav_" + name + ".csv"));
    int fixed = 0, present = 0;
    for (std::size_t i = 0; i < nav.rows.size(); ++i) {
      if (nav.number(i, "t_s") < from_s - 1e-6) continue;
      ++present;
      fixed += nav.text(i, "status") == "fixed" ? 1 : 0;
    }
    int all = 0;
    for (const auto& [t_ms, rows] : epochs) {
      const double t_s = static_cast<double>(t_ms) / 1000.0;
      all += t_s > start_s + 1e-6 && t_s >= from_s - 1e-6 ? 1 : 0;
    }
    const nlohmann::json& w = filter(k)["after_first_fix"];
    EXPECT_EQ(present, w["epochs"].get<int>()) << name;
    EXPECT_EQ(all, w["time_tags"].get<int>()) << name;
    EXPECT_LT(present, all) << name << ": the run should have data gaps in this receiver";
    EXPECT_NEAR(w["fix_rate_all_epochs"].get<double>(), static_cast<double>(fixed) / all, 1e-12) << name;
    EXPECT_LT(w["fix_rate_all_epochs"].get<double>(), w["fix_rate"].get<double>()) << name;
  }
}

}  // namespace
}  // namespace visors::test
