// Formation keeping of `visors gnss-sim` ([gnss.maneuvers] keeping; sim/formation_keeping.hpp):
// the law's sign and size on synthetic states built from mean ROE, the fit into the impulse range,
// the key, and a 12 h run of the default scenario with and without keeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/formation_keeping.hpp"
#include "visors/sim/gnss_settings.hpp"
#include "visors/sim/gnss_simulation.hpp"

namespace {

using visors::astro::KeplerianElements;
using visors::astro::RelativeOrbitalElements;
namespace roe = visors::astro::roe;
using visors::core::EarthGravityConstants;
using visors::core::StateVector;
using visors::sim::campaign_from_toml;

constexpr const char* kNavFile = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";  // the [gnss] default
constexpr double kRunDuration_s = 43200.0;  // the shortened run: 12 h

// data/scenarios/gnss_sim.toml's chief mean elements and science ROE (a_c dROE [m]).
KeplerianElements chief_mean() {
  constexpr double deg = visors::core::kDegToRad;
  return KeplerianElements{6878136.3, 0.004, 97.8 * deg, 157.5 * deg, 90.0 * deg, -90.0 * deg};
}
RelativeOrbitalElements science_roe_m() {
  RelativeOrbitalElements r;
  r << 0.015, 35.09, -34.77, 5.10, -19.09, 2.81;
  return r;
}

StateVector osculating_state(const KeplerianElements& mean) {
  const EarthGravityConstants g;
  return visors::astro::cartesian_from_keplerian(visors::astro::osculating_from_mean(mean, g).value(), g.mu);
}

// Chief and deputy true states with the deputy at mean ROE target + error (both a_c dROE [m]).
std::pair<StateVector, StateVector> states(const RelativeOrbitalElements& error_m) {
  const KeplerianElements chief = chief_mean();
  const RelativeOrbitalElements roe_now = (science_roe_m() + error_m) / chief.a;
  const KeplerianElements deputy = visors::astro::deputy_from_roe(chief, roe_now).value();
  return {osculating_state(chief), osculating_state(deputy)};
}

double mean_motion_radps() {
  const double a = chief_mean().a;
  return std::sqrt(EarthGravityConstants{}.mu / (a * a * a));
}

TEST(FormationKeepingLaw, MeanRoeOfTheStatesIsTheOneTheyWereBuiltFrom) {
  const auto [chief, deputy] = states(RelativeOrbitalElements::Zero());
  const auto roe_now = visors::sim::mean_roe_from_states(chief, deputy, EarthGravityConstants{}).value();
  const RelativeOrbitalElements roe_m = roe_now * chief_mean().a;
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(roe_m(k), science_roe_m()(k), 1e-4) << k;
}

TEST(FormationKeepingLaw, DaErrorOfPlusTenMetresGivesANegativeTangentialDvOfTheDeputy) {
  RelativeOrbitalElements error_m = RelativeOrbitalElements::Zero();
  error_m(roe::kDa) = 10.0;  // a_c da 10 m above the target: the deputy must lower its orbit
  const auto [chief, deputy] = states(error_m);
  const auto c = visors::sim::along_track_correction(chief, deputy, science_roe_m() / chief_mean().a, 0.0,
                                                     EarthGravityConstants{}).value();
  // Gauss: dv_T = (n a_c / 2)(da_target - da), the law's own numbers.
  EXPECT_NEAR(c.dv_t_deputy_mps,
              0.5 * c.mean_motion_radps * c.chief_mean_a_m * (c.da_target - c.mean_roe(roe::kDa)), 1e-9);
  // No dlambda error: da_target is the target's, and dv_T = -(n / 2) 10 m (n: the chief's mean motion).
  EXPECT_NEAR(c.da_target * chief_mean().a, science_roe_m()(roe::kDa), 1e-4);
  EXPECT_NEAR(c.dv_t_deputy_mps, -0.5 * mean_motion_radps() * 10.0, 1e-7);
  EXPECT_LT(c.dv_t_deputy_mps, 0.0);
  // The burst's random pieces already flying -2 mm/s tangentially leave that much less to command.
  const auto net = visors::sim::along_track_correction(chief, deputy, science_roe_m() / chief_mean().a, -0.002,
                                                       EarthGravityConstants{}).value();
  EXPECT_NEAR(net.dv_t_deputy_mps, c.dv_t_deputy_mps + 0.002, 1e-12);
}

TEST(FormationKeepingLaw, DlambdaErrorAloneGivesTheDriftThatRemovesItInOneOrbit) {
  const EarthGravityConstants g;
  for (const double error : {10.0, -10.0}) {
    RelativeOrbitalElements error_m = RelativeOrbitalElements::Zero();
    error_m(roe::kDlambda) = error;  // deputy ahead (+) or behind (-) its target
    const auto [chief, deputy] = states(error_m);
    const auto c = visors::sim::along_track_correction(chief, deputy, science_roe_m() / chief_mean().a, 0.0, g).value();
    // da_target - da0 = e / (3 pi); d(dlambda)/dt = -(3/2) n (da_target - da0) over 2 pi / n is -e.
    const double da_change = c.da_target - science_roe_m()(roe::kDa) / chief_mean().a;
    EXPECT_NEAR(da_change * chief_mean().a, error / (3.0 * visors::core::kPi), 1e-4) << error;
    EXPECT_NEAR(-1.5 * c.mean_motion_radps * da_change * 2.0 * visors::core::kPi / c.mean_motion_radps * chief_mean().a,
                -error, 1e-3);
    // Ahead (+): raise the orbit (dv_T > 0) to fall back; behind: lower it.
    EXPECT_GT(c.dv_t_deputy_mps * error, 0.0) << error;
    EXPECT_NEAR(c.dv_t_deputy_mps, 0.5 * mean_motion_radps() * error / (3.0 * visors::core::kPi), 1e-7);
  }
}

TEST(FormationKeepingLaw, EccentricityErrorIsRemovedInOneOrbitWithoutChangingDa) {
  RelativeOrbitalElements error_m = RelativeOrbitalElements::Zero();
  error_m(roe::kDex) = 10.0;  // a_c dex 10 m above the target
  const auto [chief, deputy] = states(error_m);
  const RelativeOrbitalElements target = science_roe_m() / chief_mean().a;
  const auto now = visors::sim::along_track_correction(chief, deputy, target, 0.0, EarthGravityConstants{}).value();
  const double n = now.mean_motion_radps;
  // At u = 0 (the chief starts at its ascending node) the whole dex error is along cos u: a negative
  // tangential impulse lowers dex (Gauss: delta(de) = (2 dv_T / (n a_c))(cos u, sin u)).
  EXPECT_NEAR(std::remainder(now.chief_mean_u_rad, 2.0 * visors::core::kPi), 0.0, 1e-6);
  const double x0 = visors::sim::eccentricity_tangential_dv_mps(now, target, 3);
  EXPECT_LT(x0, 0.0);
  EXPECT_NEAR(x0, -n * 10.0 / 3.0, 1e-7);
  // The same rule at the three bursts of the orbit: no net da, the de error removed.
  double sum = 0.0, dex_m = 0.0, dey_m = 0.0;
  for (int k = 0; k < 3; ++k) {
    auto at = now;
    at.chief_mean_u_rad = now.chief_mean_u_rad + 2.0 * visors::core::kPi * k / 3.0;
    const double x = visors::sim::eccentricity_tangential_dv_mps(at, target, 3);
    sum += x;
    dex_m += 2.0 * x / n * std::cos(at.chief_mean_u_rad);
    dey_m += 2.0 * x / n * std::sin(at.chief_mean_u_rad);
  }
  EXPECT_NEAR(sum, 0.0, 1e-12);
  EXPECT_NEAR(dex_m, -10.0, 1e-4);
  EXPECT_NEAR(dey_m, 0.0, 1e-4);
  EXPECT_EQ(visors::sim::eccentricity_tangential_dv_mps(now, target, 2), 0.0);  // two bursts: not controllable
}

TEST(FormationKeepingFit, CorrectionIsClampedIntoTheImpulseRange) {
  using visors::sim::fit_tangential_correction;
  const double min_dv = 1.0e-4, max_dv = 2.07e-3;
  const Eigen::Vector3d radial(0.002, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(fit_tangential_correction(radial, 1e-4, min_dv, max_dv), 1e-4);  // fits: unchanged
  const double room = std::sqrt(max_dv * max_dv - 0.002 * 0.002);
  EXPECT_NEAR(fit_tangential_correction(radial, 1e-3, min_dv, max_dv), room, 1e-15);    // clamped
  EXPECT_NEAR(fit_tangential_correction(radial, -1e-3, min_dv, max_dv), -room, 1e-15);
  // A tangential random piece cancelled by its correction would fall below the minimum impulse.
  const Eigen::Vector3d along(0.0, 0.002, 0.0);
  const double c = fit_tangential_correction(along, -0.00199, min_dv, max_dv);
  EXPECT_GE(std::abs(0.002 + c), min_dv - 1e-15);
  EXPECT_LE(std::abs(0.002 + c), max_dv + 1e-15);
}

TEST(FormationKeepingSettings, KeepingIsReadWrittenAndChecked) {
  const std::string base = "name = \"keep\"\n[gnss.maneuvers]\nspacecraft = \"osc\"\n";
  EXPECT_FALSE(campaign_from_toml(base).value().gnss.maneuvers.keeping);  // default
  const auto on = campaign_from_toml(base + "keeping = true\n");
  ASSERT_TRUE(on.ok()) << on.error().describe();
  EXPECT_TRUE(on->gnss.maneuvers.keeping);
  const auto again = campaign_from_toml("name = \"keep\"\n" + visors::sim::gnss_settings_to_toml(on->gnss));
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_TRUE(again->gnss.maneuvers.keeping);
  EXPECT_EQ(campaign_from_toml(base + "keeping = 1\n").error().field, "gnss.maneuvers.keeping");
  EXPECT_EQ(campaign_from_toml(base + "keeping = \"yes\"\n").error().field, "gnss.maneuvers.keeping");
}

// --- A shortened default run with and without keeping -------------------------------------

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void replace(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}

// data/scenarios/gnss_sim.toml cut to `duration_s`, the OSC maneuvering, keeping on or off, no RINEX.
std::string default_scenario(double duration_s, bool keeping) {
  std::string text = read_text(std::filesystem::path(VISORS_SOURCE_DIR) / "data/scenarios/gnss_sim.toml");
  replace(text, "duration_s = 5700.0", "duration_s = " + std::to_string(duration_s));
  replace(text, "rinex = true", "rinex = false");
  replace(text, "spacecraft = \"none\"", "spacecraft = \"osc\"");
  replace(text, "keeping = false", keeping ? "keeping = true" : "keeping = false");
  return text;
}

// min and max |r_osc - r_dsc| over truth.csv [m].
std::pair<double, double> separation_range_m(const std::filesystem::path& dir) {
  std::ifstream in(dir / "truth.csv");
  std::string line;
  std::getline(in, line);
  std::map<std::string, Eigen::Vector3d> r;  // by spacecraft, the current epoch's
  double lo = 1e300, hi = 0.0;
  while (std::getline(in, line)) {
    std::stringstream ss(line);
    std::vector<std::string> f;
    for (std::string x; std::getline(ss, x, ',');) f.push_back(x);
    r[f[1]] = Eigen::Vector3d(std::stod(f[2]), std::stod(f[3]), std::stod(f[4]));
    if (f[1] == "osc") {  // rows: dsc then osc at each epoch
      const double d = (r["osc"] - r["dsc"]).norm();
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  }
  return {lo, hi};
}

std::pair<double, double> run_and_measure(bool keeping) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("visors_keeping_" + std::to_string(::getpid()) + (keeping ? "_on" : "_off"));
  const auto s = campaign_from_toml(default_scenario(kRunDuration_s, keeping));
  EXPECT_TRUE(s.ok()) << s.error().describe();
  const auto result = visors::sim::run_gnss_simulation(*s, dir);
  EXPECT_TRUE(result.ok()) << result.error().describe();
  const auto range = separation_range_m(dir);
  std::filesystem::remove_all(dir);
  return range;
}

// 12 h of the default scenario, the OSC flying the random pairs (6 h: 18-191 m with keeping, 9-265 m
// without: too close to tell apart). Measured (seed 1): keeping 17.96 .. 190.97 m, without
// 8.67 .. 967.65 m (differential drag plus the pairs' random walk). The science formation's own
// ellipse spans 31 .. 115 m per orbit (initial ROE: a de = 35 m, a dlambda = 35 m), so "40 m" is
// the separation at the alignment point, not the envelope; the random pairs (8 mm/s per burst,
// 1/3 orbit apart) swing dlambda by up to ~45 m between bursts. Both runs ~7 s each.
TEST(FormationKeepingRun, TwelveHoursStayOnTheScienceFormationOnlyWithKeeping) {
  if (!visors::core::files::find_data_file(kNavFile)) GTEST_FAIL() << kNavFile << " not found: set VISORS_DATA_PATH";
  const auto [on_min, on_max] = run_and_measure(true);
  const auto [off_min, off_max] = run_and_measure(false);
  std::printf("keeping: separation %.2f .. %.2f m; without: %.2f .. %.2f m\n", on_min, on_max, off_min, off_max);
  EXPECT_GE(on_min, 10.0);
  EXPECT_LE(on_max, 230.0);
  EXPECT_GT(off_max, 600.0);
}

}  // namespace
