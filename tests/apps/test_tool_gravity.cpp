// `visors tool gravity` through the real binary: reference accelerations at the test point of
// Montenbruck & Gill's gravity-field exercise (O. Montenbruck, E. Gill, Satellite Orbits,
// Springer, 2000, Exercise 3-1, JGM-3) and bad input (exit code 2, field named on stderr).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

#include "apps/run_tool.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "support/geographiclib_gravity.hpp"

namespace {

// Absolute path of a data file found through the data search path (VISORS_DATA_PATH, then the
// repository's data/, which ships every file these tests read); a missing one fails the test.
std::string shared_file(const std::string& relative) {
  const auto found = visors::core::files::find_data_file(relative);
  return found ? std::filesystem::absolute(*found).string() : std::string{};
}
#define REQUIRE_SHARED(var, relative)    \
  const std::string var = shared_file(relative); \
  ASSERT_FALSE(var.empty()) << relative << " not found in the data search path (data/SOURCES.md)"

// Body-fixed position of the Montenbruck & Gill test (Satellite Orbits, 2000, Exercise 3-1) [m].
const std::string kMgPosition = R"("r_itrf":[6525919.0,1710416.0,2508886.0])";

std::string input(const std::string& model, int degree, int order, const std::string& position = kMgPosition) {
  std::string s = R"({"model":")";
  s += model;
  s += R"(","degree":)" + std::to_string(degree) + R"(,"order":)" + std::to_string(order) + ",";
  s += position;
  s += "}";
  return s;
}

double max_abs_difference(const nlohmann::json& a, double x, double y, double z) {
  return std::max({std::abs(a[0].get<double>() - x), std::abs(a[1].get<double>() - y),
                   std::abs(a[2].get<double>() - z)});
}

// JGM-3 20x20, the Montenbruck & Gill test vector (Satellite Orbits, 2000, Exercise 3-1;
// docs/algorithms/dynamics.md#gravity-worked-examples), 1e-7 m/s^2.
TEST(ToolGravity, Jgm3MontenbruckGillVector) {
  REQUIRE_SHARED(model, "gravity/JGM3.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(max_abs_difference(run.json()["a_itrf"], -6.979261862, -1.82928315091, -2.68999053339), 1e-7);
}

// GGM05S 60x60 at the same point, 1e-7 m/s^2; the model named relative to the data path. The
// reference vector is not from a publication: the potential differentiated by central differences
// with an independent Legendre recursion (docs/algorithms/dynamics.md#gravity-worked-examples);
// the test below compares with GeographicLib to 1e-12 as well.
TEST(ToolGravity, Ggm05s60WorkedVectorDataRelative) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d90.gfc");
  const auto run = visors::test::run_tool("gravity", input("gravity/GGM05S_d90.gfc", 60, 60));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_LT(max_abs_difference(run.json()["a_itrf"], -6.9792607656, -1.8292848885, -2.6899854388), 1e-7);
}

// Acceptance through the tool against an independent implementation: GeographicLib's
// SphericalHarmonic (C. F. F. Karney) with the same GGM05S coefficients, 90x90, points from 300 to
// 40,000 km altitude: relative difference < 1e-12 (the JSON numbers round-trip doubles exactly).
TEST(ToolGravity, MatchesGeographicLibAtDegree90) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d90.gfc");
  const auto field = visors::dynamics::files::read_icgem(model, 90);
  ASSERT_TRUE(field.ok()) << field.error().describe();
  const visors::test::GeographicLibGravity oracle(field.value(), 90, 90);
  const double radius = field.value().radius;
  const Eigen::Vector3d directions[] = {{1, 0.2, 0.3}, {-0.3, 0.9, -0.5}, {0.1, -0.2, -1}, {0.5, 0.5, 0.7}};
  const double altitudes[] = {300e3, 500e3, 2000e3, 20000e3, 40000e3};
  for (std::size_t k = 0; k < std::size(directions); ++k) {
    const Eigen::Vector3d r = (radius + altitudes[k]) * directions[k].normalized();
    char position[160];
    std::snprintf(position, sizeof position, "\"r_itrf\":[%.17g,%.17g,%.17g]", r.x(), r.y(), r.z());
    const auto run = visors::test::run_tool("gravity", input(model, 90, 90, position));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    Eigen::Vector3d expected;
    double potential = 0.0;
    oracle.evaluate(r, &expected, &potential);
    const auto a = run.json()["a_itrf"];
    const Eigen::Vector3d got(a[0].get<double>(), a[1].get<double>(), a[2].get<double>());
    EXPECT_LT((got - expected).norm() / expected.norm(), 1e-12) << "point " << k;
    EXPECT_LT(std::abs(run.json()["potential"].get<double>() / potential - 1.0), 1e-12) << "point " << k;
  }
}

// The header constants are echoed (GGM05S: GM 3.986004415e14, R 6378136.3) and U is GM/r to
// the J2 level (|U - GM/r| / (GM/r) ~ 1e-3).
TEST(ToolGravity, EchoesModelConstantsAndPotential) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d90.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.json()["gm"].get<double>(), 3.986004415e14);
  EXPECT_EQ(run.json()["radius"].get<double>(), 6378136.3);
  const double r = std::sqrt(6525919.0 * 6525919.0 + 1710416.0 * 1710416.0 + 2508886.0 * 2508886.0);
  const double central = 3.986004415e14 / r;
  EXPECT_LT(std::abs(run.json()["potential"].get<double>() - central) / central, 2e-3);
}

TEST(ToolGravity, UnknownModelFileNamesModel) {
  const auto run = visors::test::run_tool("gravity", input("gravity/NO_SUCH_MODEL.gfc", 20, 20));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("model"), std::string::npos) << run.err;
}

TEST(ToolGravity, DegreeAboveFileNamesDegree) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 71, 71));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("degree"), std::string::npos) << run.err;
}

TEST(ToolGravity, OrderAboveDegreeNamesOrder) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 21));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("order"), std::string::npos) << run.err;
}

TEST(ToolGravity, PositionInsideEarthNamesRItrf) {
  REQUIRE_SHARED(model, "gravity/GGM05S_d70.gfc");
  const auto run = visors::test::run_tool("gravity", input(model, 20, 20, R"("r_itrf":[0.0,0.0,6300000.0])"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("r_itrf: position is inside the Earth"), std::string::npos) << run.err;
}

TEST(ToolGravity, UnknownKeyRejected) {
  const auto run = visors::test::run_tool(
      "gravity", R"({"model":"x.gfc","degree":2,"order":2,"r_itrf":[7e6,0,0],"mu":1})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("mu"), std::string::npos) << run.err;
}

}  // namespace
