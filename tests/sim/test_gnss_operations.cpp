// `visors gnss-sim` operations: the campaign attitude with observation slews, the maneuver
// schedule and the laser rangefinder (sim/gnss_operations.hpp, sim/gnss_simulation.hpp), in short
// runs, and the [gnss.observations], [gnss.maneuvers], [gnss.lrf] tables.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include <Eigen/Geometry>

#include "visors/astro/apparent_sun.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/sim/attitude_profile.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/gnss_operations.hpp"
#include "visors/sim/gnss_simulation.hpp"
#include "visors/sim/random_stream.hpp"
#include "visors/sim/spacecraft_geometry.hpp"

namespace {

using visors::sim::campaign_from_toml;
using visors::sim::CampaignScenario;
using visors::sim::run_gnss_simulation;

constexpr const char* kNavFile = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";  // the [gnss] default

std::filesystem::path out_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("visors_gnss_ops_" + std::to_string(::getpid()) + "_" + name);
}

// The science formation (the default gnss_sim.toml's geometry), no RINEX files, for `duration` s.
std::string scenario(double duration, const std::string& gnss_extra = "", const std::string& tables = "") {
  return "name = \"gnss_ops_test\"\n[formation]\ninitial_roe_m = [0.015, 35.09, -34.77, 5.10, -19.09, 2.81]\n[gnss]\n"
         "rinex = false\nduration_s = " +
         std::to_string(duration) + "\n" + gnss_extra + tables;
}

// A CSV file as rows of fields (header dropped).
std::vector<std::vector<std::string>> read_csv(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream ss(line);
    for (std::string f; std::getline(ss, f, ',');) fields.push_back(f);
    rows.push_back(fields);
  }
  return rows;
}

std::string header(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

double num(const std::string& s) { return std::stod(s); }

// One truth.csv row (columns: sim/gnss_simulation.hpp).
struct TruthRow {
  double t_s = 0.0;
  Eigen::Vector3d r, v;
  Eigen::Quaterniond q;
};

// truth.csv by spacecraft name, in time order.
std::map<std::string, std::vector<TruthRow>> read_truth(const std::filesystem::path& dir) {
  std::map<std::string, std::vector<TruthRow>> out;
  for (const auto& f : read_csv(dir / "truth.csv")) {
    TruthRow row;
    row.t_s = num(f[0]);
    row.r = Eigen::Vector3d(num(f[2]), num(f[3]), num(f[4]));
    row.v = Eigen::Vector3d(num(f[5]), num(f[6]), num(f[7]));
    row.q = Eigen::Quaterniond(num(f[15]), num(f[16]), num(f[17]), num(f[18])).normalized();
    out[f[1]].push_back(row);
  }
  return out;
}

// Runs the scenario text into its own directory; the result's directory, or a failure.
struct SimRun {
  std::filesystem::path dir;
  nlohmann::json summary;
};

::testing::AssertionResult run(const CampaignScenario& s, const std::string& name, SimRun& out) {
  out.dir = out_dir(name);
  std::filesystem::remove_all(out.dir);
  std::filesystem::create_directories(out.dir);
  const auto result = run_gnss_simulation(s, out.dir);
  if (!result.ok()) return ::testing::AssertionFailure() << result.error().describe();
  out.summary = result->summary;
  return ::testing::AssertionSuccess();
}

CampaignScenario parse(const std::string& text) {
  auto s = campaign_from_toml(text);
  EXPECT_TRUE(s.ok()) << s.error().describe();
  return s.ok() ? *s : CampaignScenario{};
}

bool have_data() { return visors::core::files::find_data_file(kNavFile).has_value(); }

// ---------------------------------------------------------------------------------------------
// Campaign attitude and rangefinder: one 800 s run, one observation [200, 600] s (slew from 50 s,
// planned with the flight software's 1.5 deg/s; flown by an ADCS slewing at 2 deg/s, without
// control or knowledge errors so that the commanded profile shows exactly; return slew after
// 600 s: 180 deg at most, so nominal again by 720 s).

class GnssCampaignRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_data()) return;
    run_ = new SimRun;
    const auto s = campaign_from_toml(scenario(800.0, "attitude = \"campaign\"\n",
                                               "[gnss.observations]\nfirst_start_s = 200.0\nduration_s = 400.0\n"
                                               "[gnss.lrf]\nenabled = true\nbias_m = 0.01\nsigma_m = 0.002\n"
                                               "[attitude]\nslew_rate_deg_s = 2.0\npointing_sigma_arcsec = [0.0, 0.0, 0.0]\n"
                                               "jitter_sigma_arcsec = [0.0, 0.0, 0.0]\nknowledge_sigma_arcsec = [0.0, 0.0, 0.0]\n"));
    ASSERT_TRUE(s.ok()) << s.error().describe();
    const auto ok = run(*s, "campaign", *run_);
    if (!ok) {
      delete run_;
      run_ = nullptr;
    }
    ASSERT_TRUE(ok);
    truth_ = new std::map<std::string, std::vector<TruthRow>>(read_truth(run_->dir));
  }
  void SetUp() override {
    if (run_ == nullptr) GTEST_FAIL() << kNavFile << " not found (VISORS_DATA_PATH) or the run failed";
  }
  static void TearDownTestSuite() {
    if (run_ != nullptr) std::filesystem::remove_all(run_->dir);
    delete run_;
    delete truth_;
    run_ = nullptr;
    truth_ = nullptr;
  }
  static inline SimRun* run_ = nullptr;
  static inline std::map<std::string, std::vector<TruthRow>>* truth_ = nullptr;
};

// The observation window: slew lead = AttitudeProfile::required_slew_lead_s(pi) = 180 deg / 1.5
// deg/s + 30 s settling = 150 s (attitude_profile.hpp defaults, gnc.science defaults: the flight
// software plans; the ADCS's own 2 deg/s does not enter).
TEST_F(GnssCampaignRun, SummaryListsTheObservationWindow) {
  const auto& obs = run_->summary["observations"];
  ASSERT_EQ(obs.size(), 1u);
  EXPECT_NEAR(obs[0]["slew_start_s"].get<double>(), 50.0, 1e-9);
  EXPECT_NEAR(obs[0]["start_s"].get<double>(), 200.0, 1e-12);
  EXPECT_NEAR(obs[0]["end_s"].get<double>(), 600.0, 1e-12);
}

// During the observation the payload +X is at the Sun (attitude_profile.hpp: observation target;
// the quaternion is written to 1e-10, the position to 0.1 mm: both far below 1e-6 rad), and +Z is
// the zenith projected normal to X.
TEST_F(GnssCampaignRun, PayloadAtTheSunDuringTheObservation) {
  int checked = 0;
  const auto s = parse(scenario(1.0));
  for (const auto& [name, rows] : *truth_) {
    for (const TruthRow& row : rows) {
      if (row.t_s < 200.0 || row.t_s > 600.0) continue;
      // The target's apparent direction by the flight code (independent of sim/sky_truth's).
      const Eigen::Vector3d sun = visors::astro::apparent_target_unit_gcrf(s.t0 + row.t_s, {row.r, row.v}, s.target_offset_rad);
      const Eigen::Vector3d x = row.q * Eigen::Vector3d::UnitX();
      const Eigen::Vector3d z = row.q * Eigen::Vector3d::UnitZ();
      const Eigen::Vector3d zenith = row.r.normalized();
      const Eigen::Vector3d z_expected = (zenith - zenith.dot(sun) * sun).normalized();
      EXPECT_LT(std::acos(std::min(1.0, x.dot(sun))), 1e-6) << name << " t " << row.t_s;
      EXPECT_LT(x.cross(sun).norm(), 1e-6) << name << " t " << row.t_s;
      EXPECT_LT(z.cross(z_expected).norm(), 1e-6) << name << " t " << row.t_s;
      EXPECT_GT(z.dot(z_expected), 0.0);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2 * 401);
}

// Outside the slews (before 50 s; after the return slew, at most 120 s after 600 s) the attitude
// is nominal: +Z at the zenith (attitude_profile.hpp nominal target, 1e-6 rad as above); during
// the slews it is not (the antenna leaves the zenith: the slew happened).
TEST_F(GnssCampaignRun, AntennaAtTheZenithOutsideTheSlews) {
  for (const auto& [name, rows] : *truth_) {
    double max_during = 0.0;
    for (const TruthRow& row : rows) {
      const double off = (row.q * Eigen::Vector3d::UnitZ()).cross(row.r.normalized()).norm();
      if (row.t_s < 50.0 || row.t_s > 720.0) {
        EXPECT_LT(off, 1e-6) << name << " t " << row.t_s;
      }
      if (row.t_s > 50.0 && row.t_s < 600.0) max_during = std::max(max_during, off);
    }
    EXPECT_GT(max_during, 0.1) << name;
  }
}

// The body rate during a slew is the ADCS's 2 deg/s ([attitude] slew_rate_deg_s; not the 1.5 deg/s
// the flight software plans with; attitude_profile.hpp: constant-rate eigen-axis slew), seen as the
// rotation between consecutive truth quaternions (1 s apart) within the slew to the Sun (from
// 50 s; the seconds of its start and arrival are partial; the target's own motion, ~0.065 deg/s,
// is what tracking adds outside the slew).
TEST_F(GnssCampaignRun, SlewRateIsTheAdcss) {
  const auto& rows = truth_->at("osc");
  std::vector<double> fast;
  for (std::size_t k = 50; k + 1 < 200; ++k) {
    const double rate = visors::sim::rotation_angle_rad(rows[k].q, rows[k + 1].q) / visors::core::kDegToRad;
    if (rate > 0.2) fast.push_back(rate);
  }
  ASSERT_GE(fast.size(), 3u);
  for (std::size_t i = 1; i + 1 < fast.size(); ++i) EXPECT_NEAR(fast[i], 2.0, 1e-3) << i;
}

// lrf.csv: one measurement every 2 s of the window [200, 600] s (gnss_operations.hpp), and
// true_range_m is the distance between the true payload points computed here from truth.csv and
// the geometry draw of gnss_simulation.cpp (RandomStream(seed, name + ".geometry")). Tolerance:
// truth.csv positions are written to 0.1 mm, so each coordinate carries up to 0.05 mm of rounding
// (at most sqrt(3) x 0.05 mm x 2 spacecraft = 0.17 mm on the range); the quaternions (1e-10) and
// the 0.15 m lever add nothing visible.
TEST_F(GnssCampaignRun, LrfTrueRangeIsBetweenTheTruePayloadPoints) {
  EXPECT_EQ(header(run_->dir / "lrf.csv"), "t_s,range_m,true_range_m");
  const auto rows = read_csv(run_->dir / "lrf.csv");
  ASSERT_EQ(rows.size(), 201u);
  EXPECT_EQ(run_->summary["lrf_measurements"].get<int>(), 201);
  std::map<std::string, visors::sim::SpacecraftGeometry> geometry;
  for (const char* name : {"dsc", "osc"}) {
    visors::sim::RandomStream rng(1, std::string(name) + ".geometry");  // scenario seed 1 (default)
    geometry.emplace(name, visors::sim::SpacecraftGeometry::draw(visors::sim::GeometrySettings{}, rng));
  }
  double worst = 0.0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double t = num(rows[i][0]);
    EXPECT_DOUBLE_EQ(t, 200.0 + 2.0 * static_cast<double>(i));
    const auto k = static_cast<std::size_t>(std::lround(t));
    const TruthRow& o = truth_->at("osc")[k];
    const TruthRow& d = truth_->at("dsc")[k];
    ASSERT_DOUBLE_EQ(o.t_s, t);
    const Eigen::Vector3d p_osc = o.r + o.q * geometry.at("osc").payload_from_com_body_m();
    const Eigen::Vector3d p_dsc = d.r + d.q * geometry.at("dsc").payload_from_com_body_m();
    worst = std::max(worst, std::abs((p_osc - p_dsc).norm() - num(rows[i][2])));
  }
  EXPECT_LT(worst, 1.8e-4);
}

// measured - true: mean the configured bias 0.01 m, standard deviation sigma 0.002 m, over 201
// draws (bounds: mean within 3.2 sigma / sqrt(201) = 4.5e-4 m; the sample sigma within +-15 %,
// about 3 times its relative standard error 1 / sqrt(2 x 200) = 5 %).
TEST_F(GnssCampaignRun, LrfErrorHasTheBiasAndSigma) {
  const auto rows = read_csv(run_->dir / "lrf.csv");
  double sum = 0.0, sum2 = 0.0;
  for (const auto& r : rows) {
    const double e = num(r[1]) - num(r[2]);
    sum += e;
    sum2 += e * e;
  }
  const double n = static_cast<double>(rows.size());
  const double mean = sum / n;
  const double sd = std::sqrt((sum2 - n * mean * mean) / (n - 1.0));
  EXPECT_NEAR(mean, 0.01, 4.5e-4);
  EXPECT_NEAR(sd, 0.002, 0.0003);
}

// No maneuvers asked: maneuvers.csv holds its header only (gnss_simulation.hpp: written always).
TEST_F(GnssCampaignRun, ManeuversFileHasOnlyItsHeaderWithoutManeuvers) {
  EXPECT_EQ(header(run_->dir / "maneuvers.csv"),
            "t_s,spacecraft,dv_cmd_x_gcrf_mps,dv_cmd_y_gcrf_mps,dv_cmd_z_gcrf_mps,dv_x_gcrf_mps,dv_y_gcrf_mps,dv_z_gcrf_mps");
  EXPECT_TRUE(read_csv(run_->dir / "maneuvers.csv").empty());
  EXPECT_EQ(run_->summary["maneuvers"]["osc"].get<int>(), 0);
  EXPECT_EQ(run_->summary["maneuvers"]["dsc"].get<int>(), 0);
}

// ---------------------------------------------------------------------------------------------
// Maneuvers without execution errors (magnitude and direction sigmas 0, a 1e-12 N s quantum):
// a 200 s run with one burst of 4 OSC pieces at 10, 56.5, 103, 149.5 s, and the same run without
// maneuvers.

class GnssManeuverRun : public ::testing::Test {
 protected:
  static CampaignScenario ideal(const std::string& spacecraft) {
    CampaignScenario s = parse(scenario(200.0, "",
                                        "[gnss.observations]\nperiod_s = 5700.0\n[gnss.maneuvers]\nspacecraft = \"" +
                                            spacecraft + "\"\nfirst_burst_s = 10.0\n"));
    s.propulsion.magnitude_sigma = 0.0;
    s.propulsion.direction_sigma_rad = 0.0;
    s.propulsion.quantum_ns = 1e-12;
    return s;
  }
  static void SetUpTestSuite() {
    if (!have_data()) return;
    with_ = new SimRun;
    without_ = new SimRun;
    const bool ok = run(ideal("osc"), "ideal", *with_) && run(ideal("none"), "none", *without_);
    if (!ok) {
      TearDownTestSuite();
      return;
    }
  }
  void SetUp() override {
    if (with_ == nullptr) GTEST_FAIL() << kNavFile << " not found (VISORS_DATA_PATH) or the runs failed";
  }
  static void TearDownTestSuite() {
    for (SimRun* r : {with_, without_}) {
      if (r != nullptr) std::filesystem::remove_all(r->dir);
      delete r;
    }
    with_ = without_ = nullptr;
  }
  static inline SimRun* with_ = nullptr;
  static inline SimRun* without_ = nullptr;
};

// Four pieces 46.5 s apart (PropulsionSettings::spacing_s), executed == commanded to the file's
// 1e-9 m/s (%.9f) when the errors are off (propulsion.hpp: only the quantum, here 1e-12 N s, is left).
TEST_F(GnssManeuverRun, ExecutedEqualsCommandedWithoutErrors) {
  const auto rows = read_csv(with_->dir / "maneuvers.csv");
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(with_->summary["maneuvers"]["osc"].get<int>(), 4);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_DOUBLE_EQ(num(rows[i][0]), 10.0 + 46.5 * static_cast<double>(i));
    EXPECT_EQ(rows[i][1], "osc");
    const Eigen::Vector3d cmd(num(rows[i][2]), num(rows[i][3]), num(rows[i][4]));
    const Eigen::Vector3d exe(num(rows[i][5]), num(rows[i][6]), num(rows[i][7]));
    EXPECT_NEAR(cmd.norm(), 0.002, 2e-9);  // dv_mps default
    EXPECT_LT((exe - cmd).norm(), 2e-9);
  }
}

// The truth velocity jumps by the executed dv across the impulse: the difference to the run
// without maneuvers, between the epochs just before and just after each piece, changes by dv.
// Tolerance: the truth velocities are written to 1e-6 m/s per component (four roundings of
// 0.5e-6 m/s in the double difference: 2e-6 m/s per component, sqrt(3) x 2e-6 = 3.5e-6 m/s in
// norm); the dynamics of the up to 0.2 m offset over 1 s add ~1e-7 m/s (gravity gradient
// ~ 2 n^2 x 0.2 m).
TEST_F(GnssManeuverRun, TruthVelocityJumpsByTheExecutedDv) {
  const auto rows = read_csv(with_->dir / "maneuvers.csv");
  const auto with = read_truth(with_->dir).at("osc");
  const auto without = read_truth(without_->dir).at("osc");
  const auto before_dsc = read_truth(with_->dir).at("dsc");
  const auto ref_dsc = read_truth(without_->dir).at("dsc");
  ASSERT_EQ(with.size(), 201u);
  for (const auto& r : rows) {
    const double t = num(r[0]);
    const Eigen::Vector3d exe(num(r[5]), num(r[6]), num(r[7]));
    const auto k0 = static_cast<std::size_t>(std::floor(t));  // the epoch at or before the piece: pre-impulse
    const auto k1 = k0 + 1;
    const Eigen::Vector3d jump = (with[k1].v - without[k1].v) - (with[k0].v - without[k0].v);
    EXPECT_LT((jump - exe).norm(), 3.6e-6) << "t " << t;
  }
  // the first piece alone: at the next epoch the whole difference is its dv (two roundings: 1e-6
  // per component, 1.7e-6 in norm; measured 1.108e-6 with the NRLMSISE-00 truth, 2026-11)
  const Eigen::Vector3d first(num(rows[0][5]), num(rows[0][6]), num(rows[0][7]));
  EXPECT_LT((with[11].v - without[11].v - first).norm(), 1.8e-6);
  EXPECT_LT((with[10].v - without[10].v).norm(), 1e-12);  // the row at 10 s is before the impulse
  // the DSC does not maneuver: identical truth
  for (std::size_t k = 0; k < before_dsc.size(); ++k) EXPECT_EQ(before_dsc[k].v, ref_dsc[k].v);
}

// The commanded GCRF dv is the plan's RTN command (gnss_operations.hpp: the burst's unit vector
// times dv_mps) in the true RTN frame at the impulse: checked at the pieces on epochs (10, 103 s),
// whose truth row is the pre-impulse state (positions 0.1 mm, velocities 1 um/s: frame ~1e-9 rad).
TEST_F(GnssManeuverRun, CommandIsThePlansRtnDirection) {
  const CampaignScenario s = ideal("osc");
  auto profile = visors::sim::AttitudeProfile::create();
  ASSERT_TRUE(profile.ok());
  const auto plan = visors::sim::plan_gnss_operations(s, *profile, 200.0);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  const auto rows = read_csv(with_->dir / "maneuvers.csv");
  const auto truth = read_truth(with_->dir).at("osc");
  for (std::size_t i : {0u, 2u}) {
    const auto k = static_cast<std::size_t>(std::lround(num(rows[i][0])));
    const visors::core::StateVector x{truth[k].r, truth[k].v};
    const Eigen::Vector3d cmd(num(rows[i][2]), num(rows[i][3]), num(rows[i][4]));
    EXPECT_LT((visors::core::gcrf_to_rtn_matrix(x) * cmd - plan->pieces[i].dv_rtn_mps).norm(), 3e-9) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// The plan alone (no run needed).

// Bursts 2m and 2m+1 fly opposite commands, every piece of a burst the same one (gnss_operations
// .hpp); with "both" the DSC flies the opposite of the OSC at the same instant.
TEST(GnssOperationsPlan, BurstPairsAreOppositeAndBothSpacecraftOppose) {
  CampaignScenario s = parse(scenario(20000.0, "", "[gnss.maneuvers]\nspacecraft = \"both\"\ndv_mps = 0.0015\n"));
  auto profile = visors::sim::AttitudeProfile::create();
  ASSERT_TRUE(profile.ok());
  const auto plan = visors::sim::plan_gnss_operations(s, *profile, 20000.0);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  std::map<int, Eigen::Vector3d> osc_by_burst;
  std::size_t osc_pieces = 0;
  for (std::size_t i = 0; i < plan->pieces.size(); ++i) {
    const auto& p = plan->pieces[i];
    if (i > 0) {
      EXPECT_GE(p.t_s, plan->pieces[i - 1].t_s);
    }
    EXPECT_NEAR(p.dv_rtn_mps.norm(), 0.0015, 1e-15);
    if (p.craft == 0) {
      ASSERT_LT(i + 1, plan->pieces.size());
      EXPECT_EQ(plan->pieces[i + 1].t_s, p.t_s);
      EXPECT_EQ(plan->pieces[i + 1].dv_rtn_mps, Eigen::Vector3d(-p.dv_rtn_mps));  // the OSC's, just after
      continue;
    }
    ++osc_pieces;
    if (osc_by_burst.count(p.burst) != 0) {
      EXPECT_EQ(osc_by_burst[p.burst], p.dv_rtn_mps);
    }
    osc_by_burst[p.burst] = p.dv_rtn_mps;
  }
  // 20000 s: bursts at 900 + j T/3 (T = 5677 s for a = 6878136.3 m) while < 20000: j = 0..10
  EXPECT_EQ(osc_by_burst.size(), 11u);
  EXPECT_EQ(osc_pieces, 44u);
  for (int m = 0; 2 * m + 1 < 11; ++m) EXPECT_EQ(osc_by_burst[2 * m + 1], Eigen::Vector3d(-osc_by_burst[2 * m])) << m;
  EXPECT_GT((osc_by_burst[2] - osc_by_burst[0]).norm(), 1e-4);  // a new draw for each pair
}

// Pieces in [slew_start_s, end_s + 150 s] of a window are skipped (gnss_operations.hpp), and the
// period is the chief's Keplerian one (2 pi sqrt(a^3 / mu), a = 6878136.3 m, mu = 3.986004415e14:
// 5676.98 s, docs/cli/preview.md's `visors preview` line).
TEST(GnssOperationsPlan, PiecesNearObservationsAreSkipped) {
  CampaignScenario s = parse(scenario(12000.0, "attitude = \"campaign\"\n",
                                      "[gnss.observations]\nfirst_start_s = 1000.0\n"
                                      "[gnss.maneuvers]\nspacecraft = \"osc\"\nfirst_burst_s = 880.0\n"));
  auto profile = visors::sim::AttitudeProfile::create();
  ASSERT_TRUE(profile.ok());
  const auto plan = visors::sim::plan_gnss_operations(s, *profile, 12000.0);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  EXPECT_NEAR(plan->period_s, 5676.98, 0.01);
  // windows start at 1000 and 6676.98 s (slews from 850 and 6526.98 s); the third's slew would
  // start at 12203.96 s, after the run
  ASSERT_EQ(plan->windows.size(), 2u);
  // bursts 1892.33 s apart: burst 0 (880 .. 1019.5 s) lies in [850, 1160], burst 3 (6556.98 ..
  // 6696.48 s) in [6526.98, 6836.98]: 8 pieces skipped, 16 of the 6 bursts x 4 left (the 7th
  // burst, 12233.9 s, is after the run)
  EXPECT_EQ(plan->skipped_pieces, 8);
  EXPECT_EQ(plan->pieces.size(), 16u);
  for (const auto& p : plan->pieces) {
    for (const auto& w : plan->windows) {
      EXPECT_FALSE(p.t_s >= w.slew_start_s && p.t_s <= w.end_s + 150.0) << p.t_s;
    }
  }
}

// LRF epochs: every 2 s from the first epoch at or after start_s, through end_s.
TEST(GnssOperationsPlan, LrfEpochsFollowTheWindows) {
  CampaignScenario s = parse(scenario(7000.0, "attitude = \"campaign\"\n", "[gnss.lrf]\nenabled = true\n"));
  auto profile = visors::sim::AttitudeProfile::create();
  ASSERT_TRUE(profile.ok());
  const auto plan = visors::sim::plan_gnss_operations(s, *profile, 7000.0);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  ASSERT_EQ(plan->windows.size(), 1u);  // 1500 s; the next one (7176.98 s) is after the run
  ASSERT_EQ(plan->lrf_epochs.size(), 6u);  // 1500, 1502, ..., 1510
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(plan->lrf_epochs[i], 1500 + 2 * static_cast<std::int64_t>(i));
}

// ---------------------------------------------------------------------------------------------
// Maneuvers with the mission's execution errors ([propulsion] defaults: 5 % magnitude, 0.05 deg
// direction; propulsion.hpp), both spacecraft, many pieces: 27 bursts x 4 pieces x 2 in 5000 s.

TEST(GnssManeuverErrors, ExecutionErrorsHaveTheMissionSpread) {
  if (!have_data()) GTEST_FAIL() << kNavFile << " not found (VISORS_DATA_PATH)";
  const CampaignScenario s = parse(scenario(5000.0, "", "[gnss.maneuvers]\nspacecraft = \"both\"\nbursts_per_orbit = 30\n"
                                                        "dv_mps = 0.0015\nfirst_burst_s = 10.0\n"));
  SimRun r;
  ASSERT_TRUE(run(s, "errors", r));
  const auto rows = read_csv(r.dir / "maneuvers.csv");
  std::filesystem::remove_all(r.dir);
  ASSERT_GE(rows.size(), 200u);
  EXPECT_EQ(r.summary["maneuvers"]["dsc"].get<std::size_t>() + r.summary["maneuvers"]["osc"].get<std::size_t>(), rows.size());
  double sum = 0.0, sum2 = 0.0, angle2 = 0.0;
  for (const auto& f : rows) {
    const Eigen::Vector3d cmd(num(f[2]), num(f[3]), num(f[4]));
    const Eigen::Vector3d exe(num(f[5]), num(f[6]), num(f[7]));
    const double rel = (exe.norm() - cmd.norm()) / cmd.norm();
    sum += rel;
    sum2 += rel * rel;
    angle2 += std::pow(std::atan2(exe.cross(cmd).norm(), exe.dot(cmd)), 2);
  }
  const double n = static_cast<double>(rows.size());
  const double mean = sum / n;
  const double sd = std::sqrt((sum2 - n * mean * mean) / (n - 1.0));
  // magnitude: N(0, 0.05) plus the quantum (6e-5 N s on ~0.016 N s: < 0.2 %); over n >= 200
  // the mean is within 3.5 x 0.05 / sqrt(200) = 0.0124, the sigma within +-20 % (4 standard errors)
  EXPECT_NEAR(mean, 0.0, 0.0124);
  EXPECT_NEAR(sd, 0.05, 0.01);
  // direction: RMS angle = direction_sigma 0.05 deg (propulsion.hpp step 4), +-20 %; the 1e-9 m/s
  // rounding of the file is 7e-7 rad on 1.5 mm/s
  EXPECT_NEAR(std::sqrt(angle2 / n) / visors::core::kDegToRad, 0.05, 0.01);
}

// The DSC's impulse at the default dv_mps (11.35 kg x 0.002 m/s = 0.0227 N s) exceeds the
// propulsion's 0.022 N s maximum (propulsion.hpp): an error naming gnss.maneuvers.dv_mps before
// the run.
TEST(GnssManeuverErrors, UnexecutableDvIsNamed) {
  if (!have_data()) GTEST_FAIL() << kNavFile << " not found (VISORS_DATA_PATH)";
  const CampaignScenario s = parse(scenario(100.0, "", "[gnss.maneuvers]\nspacecraft = \"dsc\"\n"));
  SimRun r;
  const auto dir = out_dir("dsc_dv");
  std::filesystem::create_directories(dir);
  const auto result = run_gnss_simulation(s, dir);
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().field, "gnss.maneuvers.dv_mps");
}

// ---------------------------------------------------------------------------------------------
// The tables' keys: bad values and unknown keys are errors naming them (gnss_settings.hpp).

std::string field_of(const std::string& gnss_extra, const std::string& tables) {
  const auto s = campaign_from_toml(scenario(100.0, gnss_extra, tables));
  return s.ok() ? std::string("(accepted)") : s.error().field;
}

TEST(GnssOperationsScenario, BadValuesAreNamed) {
  const std::string o = "[gnss.observations]\n";
  EXPECT_EQ(field_of("", o + "first_start_s = -1.0\n"), "gnss.observations.first_start_s");
  EXPECT_EQ(field_of("", o + "period_s = -5.0\n"), "gnss.observations.period_s");
  EXPECT_EQ(field_of("", o + "period_s = 100.0\nduration_s = 10.0\nslew_lead_s = 100.0\n"), "gnss.observations.period_s");
  EXPECT_EQ(field_of("", o + "duration_s = 0.0\n"), "gnss.observations.duration_s");
  EXPECT_EQ(field_of("", o + "slew_lead_s = -1.0\n"), "gnss.observations.slew_lead_s");
  EXPECT_EQ(field_of("", o + "duration_s = \"long\"\n"), "gnss.observations.duration_s");
  EXPECT_EQ(field_of("", o + "window_s = 1.0\n"), "gnss.observations.window_s");
  const std::string m = "[gnss.maneuvers]\n";
  EXPECT_EQ(field_of("", m + "spacecraft = \"chief\"\n"), "gnss.maneuvers.spacecraft");
  EXPECT_EQ(field_of("", m + "bursts_per_orbit = 0\n"), "gnss.maneuvers.bursts_per_orbit");
  EXPECT_EQ(field_of("", m + "bursts_per_orbit = 2.5\n"), "gnss.maneuvers.bursts_per_orbit");
  EXPECT_EQ(field_of("", m + "pieces_per_burst = 0\n"), "gnss.maneuvers.pieces_per_burst");
  EXPECT_EQ(field_of("", m + "pieces_per_burst = 101\n"), "gnss.maneuvers.pieces_per_burst");
  EXPECT_EQ(field_of("", m + "dv_mps = 0.0\n"), "gnss.maneuvers.dv_mps");
  EXPECT_EQ(field_of("", m + "dv_mps = -0.002\n"), "gnss.maneuvers.dv_mps");
  EXPECT_EQ(field_of("", m + "first_burst_s = -10.0\n"), "gnss.maneuvers.first_burst_s");
  EXPECT_EQ(field_of("", m + "pieces = 4\n"), "gnss.maneuvers.pieces");
  const std::string l = "[gnss.lrf]\n";
  const std::string campaign = "attitude = \"campaign\"\n";
  EXPECT_EQ(field_of(campaign, l + "enabled = 1\n"), "gnss.lrf.enabled");
  EXPECT_EQ(field_of("", l + "enabled = true\n"), "gnss.lrf.enabled");  // needs attitude = "campaign"
  EXPECT_EQ(field_of(campaign, l + "interval_s = 0.0\n"), "gnss.lrf.interval_s");
  EXPECT_EQ(field_of(campaign, l + "sigma_m = -0.002\n"), "gnss.lrf.sigma_m");
  EXPECT_EQ(field_of(campaign, l + "bias_m = 5.0\n"), "gnss.lrf.bias_m");
  EXPECT_EQ(field_of(campaign, l + "noise_m = 0.1\n"), "gnss.lrf.noise_m");
  EXPECT_EQ(field_of(campaign, l + "enabled = true\n"), "(accepted)");
}

// Errors only the plan can see (they need the chief's period, the propulsion spacing, step_s).
TEST(GnssOperationsScenario, PlanErrorsAreNamed) {
  auto profile = visors::sim::AttitudeProfile::create();
  ASSERT_TRUE(profile.ok());
  const auto field = [&](const std::string& extra, const std::string& tables) {
    const auto plan = visors::sim::plan_gnss_operations(parse(scenario(6000.0, extra, tables)), *profile, 6000.0);
    return plan.ok() ? std::string("(accepted)") : plan.error().field;
  };
  const std::string campaign = "attitude = \"campaign\"\n";
  // the default 150 s lead: the first slew would start before t0
  EXPECT_EQ(field(campaign, "[gnss.observations]\nfirst_start_s = 100.0\n"), "gnss.observations.first_start_s");
  // a period of 150 s leaves no room for the 150 s lead and the 10 s observation
  EXPECT_EQ(field(campaign, "[gnss.observations]\nperiod_s = 150.0\n"), "gnss.observations.period_s");
  // 50 bursts per orbit: 113.5 s apart, less than 4 x 46.5 s
  EXPECT_EQ(field("", "[gnss.maneuvers]\nspacecraft = \"osc\"\nbursts_per_orbit = 50\n"), "gnss.maneuvers.pieces_per_burst");
  EXPECT_EQ(field(campaign, "[gnss.lrf]\nenabled = true\ninterval_s = 2.5\n"), "gnss.lrf.interval_s");
  EXPECT_EQ(field(campaign, "[gnss.lrf]\nenabled = true\n"), "(accepted)");
}

// The resolved scenario re-reads with the new tables (gnss_settings_to_toml).
TEST(GnssOperationsScenario, NewTablesSurviveTheRoundTrip) {
  const CampaignScenario s = parse(scenario(100.0, "attitude = \"campaign\"\n",
                                            "[gnss.observations]\nfirst_start_s = 321.5\nperiod_s = 4000.0\nduration_s = 12.0\n"
                                            "slew_lead_s = 160.0\n[gnss.maneuvers]\nspacecraft = \"both\"\nbursts_per_orbit = 5\n"
                                            "pieces_per_burst = 2\ndv_mps = 0.001\nfirst_burst_s = 77.0\n"
                                            "[gnss.lrf]\nenabled = true\ninterval_s = 4.0\nsigma_m = 0.003\nbias_m = -0.02\n"));
  const CampaignScenario again = parse(visors::sim::campaign_to_toml(s));
  EXPECT_EQ(visors::sim::gnss_settings_to_toml(again.gnss), visors::sim::gnss_settings_to_toml(s.gnss));
  EXPECT_EQ(again.gnss.observations.first_start_s, 321.5);
  EXPECT_EQ(again.gnss.maneuvers.spacecraft, "both");
  EXPECT_EQ(again.gnss.maneuvers.pieces_per_burst, 2);
  EXPECT_EQ(again.gnss.lrf.bias_m, -0.02);
  EXPECT_TRUE(again.gnss.lrf.enabled);
}

}  // namespace
