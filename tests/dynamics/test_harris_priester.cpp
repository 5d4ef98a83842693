// Modified Harris-Priester density (M&G 2000 sec. 3.5.2): table nodes, the interpolation, the
// bulge, the variants, the table choice and the CSV reader.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "visors/core/constants.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/harris_priester_file.hpp"
#include "visors/dynamics/harris_priester.hpp"
#include "support/temp_file.hpp"

namespace {

using visors::dynamics::AtmosphereQuery;
using visors::dynamics::embedded_harris_priester_table;
using visors::dynamics::HarrisPriesterAtmosphere;
using visors::dynamics::HarrisPriesterBulge;
using visors::dynamics::HarrisPriesterSettings;
using visors::dynamics::HarrisPriesterTable;
using visors::dynamics::files::read_harris_priester_table;

constexpr char kTableFile[] = "atmosphere/harris_priester_mg_table3-8.csv";
constexpr double kA = visors::core::kWgs84SemiMajorAxis;
constexpr double kLag = 30.0 * visors::core::kDegToRad;
constexpr double kAu = 1.495978707e11;  // [m]
// "Exact" at nodes: exp(0) = 1 except at the top node (exp(ln(ratio))), plus the cos^n weight
// of an apex direction that is 1 to rounding: a few ulp.
constexpr double kNodeRelTol = 1e-14;

// Sun on the GCRF x axis: the apex is at right ascension +30 deg in the equator.
const Eigen::Vector3d kSun(kAu, 0.0, 0.0);
const Eigen::Vector3d kApex(std::cos(kLag), std::sin(kLag), 0.0);

HarrisPriesterAtmosphere model(const HarrisPriesterSettings& settings = {}) {
  auto m = HarrisPriesterAtmosphere::create(settings);
  EXPECT_TRUE(m.ok()) << m.error().describe();
  return std::move(m).value();
}

// A query at geodetic height h (on the ITRF x axis: h = (a + h) - a exactly for integer metres)
// with the inertial position along `direction`.
AtmosphereQuery query(double height_m, const Eigen::Vector3d& direction, double f107a = 150.0) {
  AtmosphereQuery q;
  q.r_itrf = Eigen::Vector3d(kA + height_m, 0.0, 0.0);
  q.r_gcrf = (kA + height_m) * direction.normalized();
  q.sun_gcrf = kSun;
  q.activity.f107a = f107a;
  return q;
}

void expect_relative(double actual, double expected, double tol) {
  EXPECT_NEAR(actual, expected, tol * std::abs(expected)) << "relative tolerance " << tol;
}

TEST(HarrisPriester, ApexAt500KmIsTheTableMaximum) {
  // M&G Table 3.8 at 500 km: rho_M = 2.042 g/km^3 = 2.042e-12 kg/m^3 (a table node).
  expect_relative(model().density(query(500e3, kApex)), 2.042e-12, kNodeRelTol);
}

TEST(HarrisPriester, AntapexAt500KmIsTheTableMinimum) {
  // M&G Table 3.8 at 500 km: rho_m = 0.3916 g/km^3 = 3.916e-13 kg/m^3 (a table node).
  expect_relative(model().density(query(500e3, -kApex)), 3.916e-13, kNodeRelTol);
}

class SharedTable : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto path = visors::core::files::find_data_file(kTableFile);
    if (!path) GTEST_FAIL() << kTableFile << " not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
    auto table = read_harris_priester_table(*path, 150.0);
    ASSERT_TRUE(table.ok()) << table.error().describe();
    table_ = std::move(table).value();
  }
  HarrisPriesterTable table_;
};

TEST_F(SharedTable, EmbeddedTableEqualsTheFileExactly) {
  const HarrisPriesterTable embedded = embedded_harris_priester_table();
  EXPECT_EQ(embedded.height_m, table_.height_m);
  EXPECT_EQ(embedded.rho_min, table_.rho_min);
  EXPECT_EQ(embedded.rho_max, table_.rho_max);
  EXPECT_EQ(embedded.f107, 150.0);
  EXPECT_EQ(embedded.height_m.size(), 50u);  // data/SOURCES.md: 50 rows, 100-1000 km
}

TEST_F(SharedTable, EveryNodeGivesMaximumAtApexAndMinimumAtAntapex) {
  // The file's kg/m^3 columns (data/SOURCES.md, M&G Table 3.8), with n = 6 and n = 2.
  for (double n : {6.0, 2.0}) {
    HarrisPriesterSettings settings;
    settings.cosine_exponent = n;
    const HarrisPriesterAtmosphere hp = model(settings);
    for (std::size_t i = 0; i < table_.height_m.size(); ++i) {
      const double h = table_.height_m[i];
      expect_relative(hp.density(query(h, kApex)), table_.rho_max[i], kNodeRelTol);
      expect_relative(hp.density(query(h, -kApex)), table_.rho_min[i], kNodeRelTol);
    }
  }
}

TEST(HarrisPriester, BraheCrossValidationVector) {
  // brahe harris_priester.rs::test_harris_priester_cross_validation (n = 6, WGS-84 geodetic
  // height; docs/algorithms/dynamics.md#harris-priester). The points lie in the x-z plane; the height
  // does not depend on longitude, so r serves as both r_gcrf and r_itrf. Tolerance: half a unit
  // of the last published digit.
  const Eigen::Vector3d sun(24622331959.580, -133060326832.922, -57688711921.833);
  struct Case {
    Eigen::Vector3d r;
    double rho;  // [kg/m^3]
    double tol;  // [kg/m^3]
  };
  const std::vector<Case> cases{
      {{0.0, 0.0, -6466752.314}, 1.11289e-07, 0.5e-12},
      {{0.0, 0.0, -6866752.314}, 8.3078e-13, 0.5e-17},
      {{0.0, 0.0, -7266752.314}, 1.29753e-14, 0.5e-19},
      {{4878215.337, 0.0, -4847972.867}, 1.24008e-12, 0.5e-17},
      {{5161058.050, 0.0, -5130815.580}, 2.16372e-14, 0.5e-19},
  };
  const HarrisPriesterAtmosphere hp = model();
  for (const Case& c : cases) {
    AtmosphereQuery q;
    q.r_gcrf = c.r;
    q.r_itrf = c.r;
    q.sun_gcrf = sun;
    EXPECT_NEAR(hp.density(q), c.rho, c.tol) << "r = " << c.r.transpose();
  }
}

TEST(HarrisPriester, MidwayBetweenNodesIsTheGeometricMean) {
  // Exponential interpolation (M&G sec. 3.5.2) halfway between h_i and h_{i+1} gives
  // rho_i exp(ln(rho_{i+1}/rho_i)/2) = sqrt(rho_i rho_{i+1}); 500/520 km values of Table 3.8.
  const HarrisPriesterAtmosphere hp = model();
  // round-off of exp/log interpolation (a few ulp); over all expect_relative calls of this file the worst margin measured is 13x (2026-11)
  expect_relative(hp.density(query(510e3, -kApex)), std::sqrt(3.916e-13 * 2.819e-13), 1e-14);
  expect_relative(hp.density(query(510e3, kApex)), std::sqrt(2.042e-12 * 1.605e-12), 1e-14);
}

TEST(HarrisPriester, QuarterWayFollowsTheScaleHeight) {
  // rho(h) = rho_i exp((h_i - h)/H), H = (h_i - h_{i+1}) / ln(rho_{i+1}/rho_i): 800-840 km, 810 km.
  const double inv_h = std::log(5.741e-14 / 8.059e-14) / (800e3 - 840e3);
  // round-off of exp (a few ulp); see the margin measured above (2026-11)
  expect_relative(model().density(query(810e3, kApex)), 8.059e-14 * std::exp(-10e3 * inv_h), 1e-14);
}

TEST(HarrisPriester, NinetyDegreesFromApexWeightsByHalfToTheNOver2) {
  // cos^n(psi/2) at psi = 90 deg: (1/2)^(n/2) = 1/8 for n = 6, 1/2 for n = 2.
  const Eigen::Vector3d side(-kApex.y(), kApex.x(), 0.0);
  const double rho_min = 3.916e-13;  // M&G Table 3.8, 500 km
  const double rho_max = 2.042e-12;
  // round-off of cos^n (a few ulp); see the margin measured above (2026-11)
  expect_relative(model().density(query(500e3, side)), rho_min + (rho_max - rho_min) / 8.0, 1e-14);
  HarrisPriesterSettings n2;
  n2.cosine_exponent = 2.0;
  expect_relative(model(n2).density(query(500e3, side)), rho_min + (rho_max - rho_min) / 2.0, 1e-14);
}

TEST(HarrisPriester, BulgeLagsTheSunBy30DegreesInRightAscension) {
  // Toward the Sun itself (psi = 30 deg) the density is below the apex value.
  const HarrisPriesterAtmosphere hp = model();
  // M&G sec. 3.5.2: the bulge apex is 30 deg east of the Sun; measured 1.73e-12 < 2.04e-12 kg/m^3 (2026-11)
  EXPECT_LT(hp.density(query(500e3, kSun)), hp.density(query(500e3, kApex)));
  HarrisPriesterSettings no_lag;
  no_lag.bulge_lag = 0.0;
  expect_relative(model(no_lag).density(query(500e3, kSun)), 2.042e-12, kNodeRelTol);
}

TEST(HarrisPriester, ApexMaximumModeIsTheMaximumEverywhere) {
  HarrisPriesterSettings settings;
  settings.bulge = HarrisPriesterBulge::kApexMaximum;
  const HarrisPriesterAtmosphere hp = model(settings);
  expect_relative(hp.density(query(500e3, -kApex)), 2.042e-12, kNodeRelTol);  // M&G Table 3.8
  // round-off (geometric mean, as MidwayBetweenNodes); see the margin measured above (2026-11)
  expect_relative(hp.density(query(510e3, -kApex)), std::sqrt(2.042e-12 * 1.605e-12), 1e-14);
}

TEST(HarrisPriester, DensityScaleMultiplies) {
  HarrisPriesterSettings settings;
  settings.density_scale = 2.5;
  expect_relative(model(settings).density(query(500e3, kApex)), 2.5 * 2.042e-12, kNodeRelTol);
}

TEST(HarrisPriester, OutsideTheTableIsZero) {
  const HarrisPriesterAtmosphere hp = model();
  EXPECT_EQ(hp.density(query(99.999e3, kApex)), 0.0);
  EXPECT_EQ(hp.density(query(1000.001e3, kApex)), 0.0);
  EXPECT_EQ(hp.density(query(-100e3, kApex)), 0.0);
  // Both end nodes are inside (M&G Table 3.8: 100 km 4.974e-7, 1000 km rho_M 1.810e-14).
  expect_relative(hp.density(query(100e3, kApex)), 4.974e-07, kNodeRelTol);
  expect_relative(hp.density(query(1000e3, kApex)), 1.810e-14, kNodeRelTol);
}

TEST(HarrisPriester, HeightIsGeodeticFromItrf) {
  // Over the pole: h = |z| - b (WGS-84 b = 6356752.314245 m); 500 km node at the antapex.
  AtmosphereQuery q = query(0.0, -kApex);
  const double b = kA * (1.0 - visors::core::kWgs84Flattening);
  q.r_itrf = Eigen::Vector3d(0.0, 0.0, b + 500e3);
  expect_relative(model().density(q), 3.916e-13, 1e-12);  // (b + h) - b rounds to ~1e-9 m
}

TEST(HarrisPriester, TableChosenByClosestF107Level) {
  // Two tables: M&G at 150 sfu and a synthetic one (x3) at 250 sfu.
  HarrisPriesterTable high = embedded_harris_priester_table();
  high.f107 = 250.0;
  for (double& rho : high.rho_min) rho *= 3.0;
  for (double& rho : high.rho_max) rho *= 3.0;
  auto created = HarrisPriesterAtmosphere::create({high, embedded_harris_priester_table()});
  ASSERT_TRUE(created.ok()) << created.error().describe();
  const HarrisPriesterAtmosphere& hp = *created;
  EXPECT_EQ(hp.tables()[hp.table_index(215.3)].f107, 250.0);  // 2024-10-01 f107a (space-weather file)
  EXPECT_EQ(hp.tables()[hp.table_index(120.0)].f107, 150.0);
  EXPECT_EQ(hp.tables()[hp.table_index(200.0)].f107, 150.0);  // tie: the lower level
  expect_relative(hp.density(query(500e3, kApex, 215.3)), 3.0 * 2.042e-12, kNodeRelTol);
  expect_relative(hp.density(query(500e3, kApex, 160.0)), 2.042e-12, kNodeRelTol);
}

TEST(HarrisPriester, SingleTableIsAlwaysUsed) {
  const HarrisPriesterAtmosphere hp = model();
  EXPECT_EQ(hp.table_index(60.0), 0u);
  EXPECT_EQ(hp.table_index(300.0), 0u);
  expect_relative(hp.density(query(500e3, kApex, 300.0)), 2.042e-12, kNodeRelTol);
}

TEST(HarrisPriester, CreateRejectsBadSettings) {
  HarrisPriesterSettings s;
  s.cosine_exponent = 0.0;
  EXPECT_EQ(HarrisPriesterAtmosphere::create(s).error().field, "cosine_exponent");
  s = {};
  s.bulge_lag = std::nan("");
  EXPECT_EQ(HarrisPriesterAtmosphere::create(s).error().field, "bulge_lag");
  s = {};
  s.density_scale = -1.0;
  EXPECT_EQ(HarrisPriesterAtmosphere::create(s).error().field, "density_scale");
}

TEST(HarrisPriester, CreateRejectsBadTables) {
  EXPECT_EQ(HarrisPriesterAtmosphere::create(std::vector<HarrisPriesterTable>{}).error().field,
            "tables");
  HarrisPriesterTable bad = embedded_harris_priester_table();
  bad.rho_min[3] = 1.0;  // > rho_max
  EXPECT_EQ(HarrisPriesterAtmosphere::create({bad}).error().field, "tables[0].node[3]");
  const auto same_level = HarrisPriesterAtmosphere::create(
      {embedded_harris_priester_table(), embedded_harris_priester_table()});
  EXPECT_EQ(same_level.error().field, "tables");
}

// Reader errors, on temporary files.
// A temporary CSV file with the given text.
class TempCsv : public visors::test::TempFile {
 public:
  explicit TempCsv(const std::string& text) : TempFile(text, ".csv") {}
};

constexpr char kHeader[] =
    "altitude_km,rho_min_g_per_km3,rho_max_g_per_km3,rho_min_kg_per_m3,rho_max_kg_per_m3\n";

std::string csv(const std::string& rows) { return std::string(kHeader) + rows; }

TEST(HarrisPriesterReader, ReadsAWellFormedFile) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,1,2.490e-08,2.490e-08\n"));
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_TRUE(t.ok()) << t.error().describe();
  EXPECT_EQ(t->height_m, (std::vector<double>{100e3, 120e3}));
  EXPECT_EQ(t->rho_max[1], 2.490e-08);
}

TEST(HarrisPriesterReader, MalformedNumberNamesLineAndColumn) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,1,2.4x0e-08,2.490e-08\n"));
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("rho_min_kg_per_m3"), std::string::npos) << t.error().message;
}

TEST(HarrisPriesterReader, NonIncreasingHeightIsRejected) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n100,1,1,2.490e-08,2.490e-08\n"));
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("increase"), std::string::npos) << t.error().message;
}

TEST(HarrisPriesterReader, NonPositiveDensityIsRejected) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,1,0,2.490e-08\n"));
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("rho_min"), std::string::npos) << t.error().message;
}

TEST(HarrisPriesterReader, MinimumAboveMaximumIsRejected) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,1,3e-08,2.490e-08\n"));
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 3");
  EXPECT_NE(t.error().message.find("exceeds"), std::string::npos) << t.error().message;
}

TEST(HarrisPriesterReader, MissingColumnIsNamed) {
  const TempCsv f("altitude_km,rho_min_kg_per_m3\n100,4.974e-07\n");
  const auto t = read_harris_priester_table(f.path(), 150.0);
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().field, "line 1");
  EXPECT_NE(t.error().message.find("rho_max_kg_per_m3"), std::string::npos) << t.error().message;
}

TEST(HarrisPriesterReader, WrongFieldCountIsRejected) {
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,2.490e-08,2.490e-08\n"));
  EXPECT_EQ(read_harris_priester_table(f.path(), 150.0).error().field, "line 3");
}

TEST(HarrisPriesterReader, MissingFileAndBadLevelAreErrors) {
  EXPECT_FALSE(read_harris_priester_table("/nonexistent/hp.csv", 150.0).ok());
  const TempCsv f(csv("100,1,1,4.974e-07,4.974e-07\n120,1,1,2.490e-08,2.490e-08\n"));
  EXPECT_EQ(read_harris_priester_table(f.path(), 0.0).error().field, "f107");
}

}  // namespace
