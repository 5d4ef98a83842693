// The assembled force model: configuration checks, its creation from loaded data and the loading
// with fallbacks (dynamics/files/force_model_files.hpp), term magnitudes, the truth/on-board model
// mismatch and the differential accelerations between the two spacecraft
// (docs/algorithms/dynamics.md#truth-and-on-board-mismatch).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/sun_moon.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/files/nrlmsise00_file.hpp"
#include "visors/dynamics/files/space_weather_file.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/harris_priester.hpp"
#include "visors/dynamics/nrlmsise00.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"
#include "support/temp_file.hpp"

namespace visors::dynamics {
namespace {

using core::GpsTime;

const GpsTime kEpoch = GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();

core::StateVector mission_chief(double gm) {
  return astro::cartesian_from_keplerian(
      {6378136.3 + 500e3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad, 90.0 * core::kDegToRad, 0.0}, gm);
}

// The data files `config` names that the search path does not find (empty: all present). Tests
// skip on exactly this, never on "any warning": a model warning is a result to test.
std::string missing_files(const ForceModelConfig& config) {
  std::string missing;
  for (const std::string* file : {&config.gravity.model, &config.drag.space_weather, &config.earth_frame.eop}) {
    if (!file->empty() && !core::files::find_data_file(*file)) missing += " " + *file;
  }
  return missing;
}

ForceModel make(const ForceModelConfig& config, const SpacecraftProperties& sc = {}) {
  auto forces = files::load_force_model(config, sc);
  EXPECT_TRUE(forces.ok()) << forces.error().describe();
  return std::move(forces).value();
}

TEST(ForceModel, RejectsANonPositiveMass) {
  SpacecraftProperties sc;
  sc.mass = 0.0;
  EXPECT_EQ(files::load_force_model(ForceModelConfig::onboard(), sc).error().field, "spacecraft.mass");
}

TEST(ForceModel, MissingGravityFileIsAnErrorWithoutFallback) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.gravity.model = "gravity/no_such_model.gfc";
  c.gravity.allow_embedded_fallback = false;
  EXPECT_EQ(files::load_force_model(c, {}).error().field.rfind("gravity.model", 0), 0u);
}

TEST(ForceModel, MissingGravityFileFallsBackToTheEmbeddedFieldWithAWarning) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.gravity.model = "gravity/no_such_model.gfc";
  const ForceModel forces = make(c);
  ASSERT_FALSE(forces.warnings().empty());
  EXPECT_NE(forces.warnings().front().find("embedded"), std::string::npos);
}

// Like the gravity and EOP files: a missing space-weather file is a recorded warning (the
// configured constant activity is used), so the truth preset runs on a machine without data.
TEST(ForceModel, MissingSpaceWeatherFileFallsBackWithAWarning) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.drag.space_weather = "space_weather/none.csv";
  const ForceModel forces = make(c);
  const auto& w = forces.warnings();
  EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& m) { return m.rfind("drag.space_weather", 0) == 0; }));
}

// Files missing, fallbacks allowed: one warning per fallback, in the order gravity, degree
// truncation, space weather, EOP (the texts `visors run` prints).
TEST(ForceModel, FallbackWarningsComeInTheOrderOfTheConfiguration) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.gravity.model = "gravity/no_such_model.gfc";
  c.drag.space_weather = "space_weather/none.csv";
  c.earth_frame.eop = "eop/none.txt";
  const ForceModel forces = make(c);
  ASSERT_EQ(forces.warnings().size(), 4u);
  EXPECT_EQ(forces.warnings()[0].rfind("gravity.model: gravity/no_such_model.gfc: gravity model file not found", 0), 0u);
  EXPECT_EQ(forces.warnings()[1], "gravity.degree: truncated to 8, the maximum of the field in use");
  EXPECT_EQ(forces.warnings()[2],
            "drag.space_weather: 'space_weather/none.csv' not found; constant f107/f107a/ap of the configuration");
  EXPECT_EQ(forces.warnings()[3], "earth_frame.eop: 'eop/none.txt' not found; zero polar motion and UT1-UTC");
}

// The spacecraft is checked before any file is looked for.
TEST(ForceModel, InvalidSpacecraftComesBeforeAMissingGravityFile) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.gravity.model = "gravity/no_such_model.gfc";
  c.gravity.allow_embedded_fallback = false;
  SpacecraftProperties sc;
  sc.cd = -1.0;
  EXPECT_EQ(files::load_force_model(c, sc).error().field, "spacecraft.cd");
}

// An unreadable space-weather file is reported after the drag settings, which come first.
TEST(ForceModel, InvalidDragSettingsComeBeforeAnUnreadableSpaceWeatherFile) {
  const visors::test::TempFile garbage("not a space-weather file\n", ".csv");
  ForceModelConfig c = ForceModelConfig::onboard();
  c.drag.space_weather = garbage.path().string();
  EXPECT_EQ(files::load_force_model(c, {}).error().field.rfind("drag.space_weather", 0), 0u);
  c.drag.cosine_exponent = 0;
  EXPECT_EQ(files::load_force_model(c, {}).error().field, "drag.cosine_exponent");
}

// The flight creation reads no file: the data are given, with the fallbacks the loader took.
TEST(ForceModel, CreateTakesTheDataAndReadsNoFile) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.gravity.model = "gravity/no_such_model.gfc";
  c.gravity.allow_embedded_fallback = false;  // loading would fail
  c.earth_frame.eop = "eop/none.txt";
  ForceModelData data;
  data.gravity_field = embedded_gravity_field();
  data.eop_fallback = "eop fallback";
  auto forces = ForceModel::create(c, {}, std::move(data));
  ASSERT_TRUE(forces.ok()) << forces.error().describe();
  EXPECT_EQ(forces->warnings(), (std::vector<std::string>{
                                    "gravity.degree: truncated to 8, the maximum of the field in use", "eop fallback"}));
  EXPECT_EQ(forces->gm(), embedded_gravity_field().gm);
}

// Outside the space-weather file's dates (2024-07-01..2025-01-31) the configured activity is used
// and each such UTC day is counted once (also across the truth's 3-hour ap intervals), so the
// caller can warn.
TEST(ForceModel, CountsDaysOutsideTheSpaceWeatherTable) {
  ForceModel forces = make(ForceModelConfig::truth());
  const GpsTime outside = GpsTime::parse("2025-03-01T00:00:00", core::TimeScale::kUtc).value();
  const core::StateVector x = mission_chief(forces.gm());
  for (double dt : {0.0, 3600.0, 5 * 3600.0, 86400.0 + 10.0}) (void)forces.acceleration(outside + dt, x);
  if (const auto missing = missing_files(ForceModelConfig::truth()); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  EXPECT_EQ(forces.space_weather_misses(), 2);
  EXPECT_EQ(forces.ap_history_misses(), 0);
}

// The table starts 2024-07-01: on 07-02 the daily activity exists (f107 of 07-01) but not the 57 h
// of ap history, so those 3-hour intervals run NRLMSISE-00 in its daily-Ap mode and are counted.
TEST(ForceModel, CountsIntervalsWithoutApHistory) {
  if (const auto missing = missing_files(ForceModelConfig::truth()); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  ForceModel forces = make(ForceModelConfig::truth());
  const GpsTime day2 = GpsTime::parse("2024-07-02T00:00:00", core::TimeScale::kUtc).value();
  const core::StateVector x = mission_chief(forces.gm());
  for (double dt : {0.0, 3600.0, 4 * 3600.0}) (void)forces.acceleration(day2 + dt, x);  // intervals 0, 0, 1
  EXPECT_EQ(forces.ap_history_misses(), 2);
  EXPECT_EQ(forces.space_weather_misses(), 0);
}

// The truth's NRLMSISE-00 (docs/nrlmsise00.md): the density the force model uses for drag at the mission
// chief (500 km) equals the model evaluated directly at the same point with the activity of the
// space-weather table (f107, f107a, daily Ap and the 3-hourly ap history): the plumbing. The
// second time is in the same UTC day but another 3-hour interval of the storm of 2024-10-10
// (the space-weather file's 3-hourly ap), so a model that refreshed its ap history only daily
// would fail.
TEST(ForceModel, TruthDensityIsNrlmsise00WithTheObservedApHistory) {
  const ForceModelConfig truth = ForceModelConfig::truth();
  if (const auto missing = missing_files(truth); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  ForceModel forces = make(truth);
  ASSERT_TRUE(forces.warnings().empty()) << forces.warnings().front();
  const auto table = files::read_space_weather_file(*core::files::find_data_file(truth.drag.space_weather)).value();
  const auto coefficients =
      files::read_nrlmsise00_coefficients(*core::files::find_data_file(truth.drag.nrlmsise00_coefficients)).value();
  const Nrlmsise00Atmosphere msis = Nrlmsise00Atmosphere::create(coefficients).value();
  const core::StateVector x = mission_chief(forces.gm());
  for (const char* when : {"2024-10-01T00:00:00", "2024-10-10T01:00:00", "2024-10-10T13:30:00"}) {
    const GpsTime t = GpsTime::parse(when, core::TimeScale::kUtc).value();
    const AccelerationTerms terms = forces.acceleration_terms(t, x);
    AtmosphereQuery q;
    q.t = t;
    q.r_gcrf = x.r;
    // The Earth-fixed point with zero EOP (the force model applies the table's, below).
    q.r_itrf = core::gcrf_to_itrf_matrix(t, core::EarthOrientation{}) * x.r;
    q.activity = table.at(t).value();
    q.activity.ap_history = table.ap_history(t).value();
    const double direct = msis.density(q);
    std::printf("[ measured ] %s: truth density at the chief %.4e kg/m^3 (height %.1f km)\n", when, terms.density,
                Nrlmsise00Atmosphere::input_at(q).altitude_km);
    // EOP (~0.3" ~ 10 m of position) and frame caching change the geodetic point by ~10 m, the
    // density by ~10 m / 60 km scale height ~ 2e-4: bound 1e-3 relative.
    EXPECT_NEAR(terms.density, direct, 1e-3 * direct) << when;
  }
}

// The magnitude at 500 km in October 2024 (F10.7 ~ 245, solar maximum): between the mean-activity
// Harris-Priester antapex minimum 3.9e-13 and five times its apex maximum 2.04e-12 kg/m^3 at 500 km
// (Montenbruck & Gill 2000, Table 3.8): high activity lifts the density above the mean-activity
// envelope by a factor of a few, not by orders of magnitude.
TEST(ForceModel, TruthDensityAtFiveHundredKilometresInOctober2024IsPlausible) {
  const ForceModelConfig truth = ForceModelConfig::truth();
  if (const auto missing = missing_files(truth); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  ForceModel forces = make(truth);
  // One orbit, every 60 s (the state rotated along the orbit by the mean motion is enough here).
  double low = 1.0, high = 0.0, sum = 0.0;
  int n = 0;
  for (double dt = 0.0; dt < 5677.0; dt += 60.0) {
    astro::KeplerianElements e{6378136.3 + 500e3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad,
                               90.0 * core::kDegToRad, 2.0 * core::kPi * dt / 5677.0};
    const double rho = forces.acceleration_terms(kEpoch + dt, astro::cartesian_from_keplerian(e, forces.gm())).density;
    low = std::min(low, rho);
    high = std::max(high, rho);
    sum += rho;
    ++n;
  }
  std::printf("[ measured ] truth density over one orbit on 2024-10-01: %.3e .. %.3e, mean %.3e kg/m^3\n", low, high,
              sum / n);
  EXPECT_GT(low, 3.9e-13);
  EXPECT_LT(high, 5.0 * 2.04e-12);
}

// Without its coefficient file the NRLMSISE-00 truth falls back to the Harris-Priester maximum
// densities, with a warning (like the other file fallbacks).
TEST(ForceModel, MissingNrlmsise00CoefficientsFallBackToHarrisPriesterMaximum) {
  ForceModelConfig c = ForceModelConfig::truth();
  c.drag.nrlmsise00_coefficients = "atmosphere/none.txt";
  ForceModel forces = make(c);
  const auto& w = forces.warnings();
  EXPECT_TRUE(std::any_of(w.begin(), w.end(), [](const std::string& m) {
    return m == "drag.nrlmsise00_coefficients: 'atmosphere/none.txt' not found; Harris-Priester maximum densities "
                "instead of NRLMSISE-00";
  }));
  ForceModelConfig hp = c;
  hp.drag.atmosphere = AtmosphereKind::kHarrisPriesterMaximum;
  ForceModel reference = make(hp);
  const core::StateVector x = mission_chief(forces.gm());
  // The same model: identical densities (reference: the Harris-Priester maximum itself).
  EXPECT_EQ(forces.acceleration_terms(kEpoch, x).density, reference.acceleration_terms(kEpoch, x).density);
}

TEST(ForceModel, UnreadableNrlmsise00CoefficientsAreAnErrorNamingTheFile) {
  const visors::test::TempFile garbage("array pt 1 150\n1 2 3\n", ".txt");
  ForceModelConfig c = ForceModelConfig::truth();
  c.drag.nrlmsise00_coefficients = garbage.path().string();
  const auto forces = files::load_force_model(c, {});
  ASSERT_FALSE(forces.ok());
  EXPECT_EQ(forces.error().field, "drag.nrlmsise00_coefficients.line 2");
}

// ForceModel::create asked for NRLMSISE-00 without its tables: the same fallback, with a warning.
TEST(ForceModel, CreateWithoutNrlmsise00TablesWarns) {
  ForceModelConfig c = ForceModelConfig::onboard();
  c.drag.atmosphere = AtmosphereKind::kNrlmsise00;
  ForceModelData data;
  data.gravity_field = embedded_gravity_field();
  auto forces = ForceModel::create(c, {}, std::move(data));
  ASSERT_TRUE(forces.ok()) << forces.error().describe();
  ASSERT_EQ(forces->warnings().size(), 2u);  // and the degree truncation of the embedded field
  EXPECT_EQ(forces->warnings()[1].rfind("drag.atmosphere: NRLMSISE-00 without its coefficient tables", 0), 0u);
}

// Orders of magnitude at 500 km (Montenbruck & Gill 2000, Fig. 3.1, scaled to A/m = 0.031 m^2/kg):
// central gravity 8.4 m/s^2, Moon ~1e-6, Sun ~5e-7, SRP 2.5e-7 in sunlight, drag 1e-7..1e-5.
TEST(ForceModel, TermMagnitudesAtFiveHundredKilometres) {
  ForceModel forces = make(ForceModelConfig::truth());
  const AccelerationTerms a = forces.acceleration_terms(kEpoch, mission_chief(forces.gm()));
  // GM/r^2 at r = 6878 km is 8.43 m/s^2 (M&G Fig. 3.1 above); measured 0.040 (J2 and latitude) (2026-11)
  EXPECT_NEAR(a.gravity.norm(), 8.43, 0.05);
  EXPECT_GT(a.moon.norm(), 3e-7);
  EXPECT_LT(a.moon.norm(), 2e-6);
  EXPECT_GT(a.sun.norm(), 1e-7);
  EXPECT_LT(a.sun.norm(), 1e-6);
  EXPECT_LE(a.srp.norm(), 4.56e-6 * 1.8 * 0.35 / 11.35 * 1.04);  // perihelion factor (1/0.983)^2
  EXPECT_GT(a.drag.norm(), 1e-7);
  EXPECT_LT(a.drag.norm(), 1e-5);
  EXPECT_GT(a.density, 0.0);
}

// Drag opposes the velocity relative to the co-rotating atmosphere.
TEST(ForceModel, DragOpposesTheRelativeWind) {
  ForceModel forces = make(ForceModelConfig::onboard());
  const core::StateVector x = mission_chief(forces.gm());
  const AccelerationTerms a = forces.acceleration_terms(kEpoch, x);
  const Eigen::Vector3d wind = x.v - Eigen::Vector3d(0, 0, core::kEarthRotationRate).cross(x.r);
  // analytic: -1 to round-off (drag is antiparallel to the wind); measured -1 (2026-11)
  EXPECT_LT(a.drag.normalized().dot(wind.normalized()), -0.999999);
}

// Empirical accelerations are given in RTN: a pure R component points along r.
TEST(ForceModel, EmpiricalAccelerationIsInTheRtnFrame) {
  ForceModel forces = make(ForceModelConfig::onboard());
  forces.set_empirical_acceleration_rtn({1e-6, 0, 0});
  const core::StateVector x = mission_chief(forces.gm());
  const AccelerationTerms a = forces.acceleration_terms(kEpoch, x);
  // loose: measured 2.1e-22 m/s^2 (2026-11), bound 1e-18 ~5000x above round-off (ulp 2e-22)
  EXPECT_NEAR(a.empirical.dot(x.r.normalized()), 1e-6, 1e-18);
}

// Model mismatch (docs/algorithms/dynamics.md#truth-and-on-board-mismatch): one orbit of the
// mission chief with the truth and the on-board models from the same initial state, RTN difference
// of the positions.
Eigen::Vector3d mismatch_after_one_orbit(ForceModelConfig truth_config, ForceModelConfig onboard_config) {
  ForceModel truth = make(truth_config);
  ForceModel onboard = make(onboard_config);
  const core::StateVector x0 = mission_chief(truth.gm());
  const GpsTime t1 = kEpoch + 5677.0;  // one orbital period of a = R_E + 500 km
  PropagatorSettings settings;
  settings.step_s = 5.0;
  OrbitPropagator tp = OrbitPropagator::create(truth, settings).value();
  OrbitPropagator op = OrbitPropagator::create(onboard, settings).value();
  const core::StateVector xt = tp.propagate_to(kEpoch, x0, t1).value();
  const core::StateVector xo = op.propagate_to(kEpoch, x0, t1).value();
  return core::gcrf_to_rtn_matrix(xt) * (xo.r - xt.r);
}

// The along-track drag mismatch dominates: the truth's NRLMSISE-00 at the observed October 2024
// activity (F10.7 ~ 245) exceeds the on-board mean-activity Harris-Priester by ~1e-12 kg/m^3 at
// 500 km, i.e. a tangential f = drho/2 Cd A/m v^2 ~ 2e-6 m/s^2, which drifts (3/2) f t^2 ~ 100 m
// along-track in one orbit (Clohessy-Wiltshire secular term): the mismatch the mission's filter
// absorbs with empirical accelerations. Needs the space-weather file (without it the truth's
// activity is the configured mean, the on-board level).
TEST(ForceModel, TruthAndOnboardModelsDifferByTheDragMismatchOverOneOrbit) {
  if (const auto missing = missing_files(ForceModelConfig::truth()); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  const Eigen::Vector3d d_rtn = mismatch_after_one_orbit(ForceModelConfig::truth(), ForceModelConfig::onboard());
  std::printf("truth vs on-board after one orbit: |dr| %.3f m, RTN (%.3f, %.3f, %.3f) m\n", d_rtn.norm(),
              d_rtn.x(), d_rtn.y(), d_rtn.z());
  // analytic (3/2) f t^2 ~ 100 m above; measured 109 m with NRLMSISE-00 (128 m with the former
  // Harris-Priester-maximum truth), 2026-11; bounds 30 .. 500 m
  EXPECT_GT(std::abs(d_rtn.y()), 30.0);
  EXPECT_LT(std::abs(d_rtn.y()), 500.0);
}

// Without drag the mismatch is metres: GGM01S 20x20 vs GGM05S 60x60, cylindrical vs conical
// shadow, on-board vs full Earth orientation.
TEST(ForceModel, TruthAndOnboardModelsWithoutDragDifferByMetres) {
  ForceModelConfig truth = ForceModelConfig::truth();
  ForceModelConfig onboard = ForceModelConfig::onboard();
  if (const auto missing = missing_files(truth) + missing_files(onboard); !missing.empty()) {
    GTEST_FAIL() << "not found (set VISORS_DATA_PATH):" << missing;
  }
  truth.drag.enabled = false;
  onboard.drag.enabled = false;
  const Eigen::Vector3d d_rtn = mismatch_after_one_orbit(truth, onboard);
  std::printf("truth vs on-board without drag after one orbit: |dr| %.3f m, RTN (%.3f, %.3f, %.3f) m\n",
              d_rtn.norm(), d_rtn.x(), d_rtn.y(), d_rtn.z());
  // "metres" above; measured 8.45 m (2026-11), bounds 0.01 .. 20 m
  EXPECT_GT(d_rtn.norm(), 0.01);
  EXPECT_LT(d_rtn.norm(), 20.0);
}

// The differential acceleration between two spacecraft 40 m apart (OSC sunward of DSC, as in
// science mode), per term. Gravity's differential is checked against the
// full-field gravity gradient times the separation (second-order remainder ~ 40 m / 6878 km).
TEST(ForceModel, DifferentialAccelerationsFortyMetresApart) {
  SpacecraftProperties osc;
  osc.mass = 10.62;  // Guffanti et al., AAS 23-149, 2023, Table 4: OSC 10.62 kg, DSC 11.35 kg
  ForceModel dsc_forces = make(ForceModelConfig::truth());
  ForceModel osc_forces = make(ForceModelConfig::truth(), osc);
  const core::StateVector dsc = mission_chief(dsc_forces.gm());
  const Eigen::Vector3d separation = 40.0 * astro::sun_position_gcrf(kEpoch).normalized();
  const core::StateVector osc_state{dsc.r + separation, dsc.v};
  const AccelerationTerms a_dsc = dsc_forces.acceleration_terms(kEpoch, dsc);
  const AccelerationTerms a_osc = osc_forces.acceleration_terms(kEpoch, osc_state);
  std::printf("differential acceleration OSC - DSC, 40 m sunward [m/s^2]: gravity %.3e, drag %.3e, "
              "SRP %.3e, Sun %.3e, Moon %.3e\n",
              (a_osc.gravity - a_dsc.gravity).norm(), (a_osc.drag - a_dsc.drag).norm(),
              (a_osc.srp - a_dsc.srp).norm(), (a_osc.sun - a_dsc.sun).norm(), (a_osc.moon - a_dsc.moon).norm());

  // Independent check of the gravity differential: gradient of the same field (60x60 GGM05S
  // or the embedded fallback) in ITRF, rotated to GCRF with the full IAU 2006/2000A frame.
  const auto file = files::load_gravity_field(dsc_forces.config().gravity.model, 60);
  const GravityField field = file.ok() ? file.value() : embedded_gravity_field();
  auto sh = SphericalHarmonicGravity::create(field, std::min(60, field.max_degree), std::min(60, field.max_degree));
  ASSERT_TRUE(sh.ok());
  SphericalHarmonicGravity gravity = std::move(sh).value();
  const Eigen::Matrix3d to_itrf = core::gcrf_to_itrf_matrix(kEpoch, {});
  const Eigen::Vector3d expected =
      to_itrf.transpose() * gravity.gradient(to_itrf * (dsc.r + 0.5 * separation)) * to_itrf * separation;
  // second-order remainder 40 m / 6878 km ~ 6e-6 of the gradient term (above); measured 7.7e-13 m/s^2 vs bound 5.0e-11 (2026-11)
  EXPECT_LT(((a_osc.gravity - a_dsc.gravity) - expected).norm(), 1e-6 * expected.norm());
}

}  // namespace
}  // namespace visors::dynamics
