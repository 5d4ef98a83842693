// `visors tool sun` through the real binary: the flight library's apparent Sun at the stated UTC
// instant, the target offset, and the errors naming their field.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "apps/run_tool.hpp"
#include "visors/astro/apparent_sun.hpp"
#include "visors/core/gps_time.hpp"

namespace {

constexpr double kRadToArcsec = 180.0 / M_PI * 3600.0;
constexpr char kState[] = R"("r_gcrf":[6878136.3,0,0],"v_gcrf":[0,1045.1,7540.6])";

Eigen::Vector3d vec(const nlohmann::json& j) { return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()}; }

double angle_arcsec(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kRadToArcsec;
}

const visors::core::StateVector kObserver{{6878136.3, 0.0, 0.0}, {0.0, 1045.1, 7540.6}};

TEST(ToolSun, ApparentDirectionIsTheLibrarysAtTheUtcInstant) {
  // 2024-10-01T12:00:00 UTC = 12:00:18 GPS. Reading the time as GPS would move the Sun by
  // 18 s x 0.041"/s = 0.74"; the bound 0.001" tells the two apart.
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2024-10-01T12:00:00",)") + kState + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto t = *visors::core::GpsTime::parse("2024-10-01T12:00:00", visors::core::TimeScale::kUtc);
  const auto view = visors::astro::sun_view(t, kObserver);
  EXPECT_LT(angle_arcsec(vec(run.json()["apparent_unit_gcrf"]), view.apparent_unit_gcrf), 1e-3);
}

TEST(ToolSun, GeometricDirectionAndDistanceAreTheLibrarys) {
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2024-10-01T12:00:00",)") + kState + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto t = *visors::core::GpsTime::parse("2024-10-01T12:00:00", visors::core::TimeScale::kUtc);
  const auto view = visors::astro::sun_view(t, kObserver);
  EXPECT_LT(angle_arcsec(vec(run.json()["geometric_unit_gcrf"]), view.geometric_unit_gcrf), 1e-6);
  EXPECT_NEAR(run.json()["distance_m"].get<double>(), view.distance_m, 1e-3);
}

TEST(ToolSun, TargetLiesAtItsOffsetFromTheApparentSun) {
  // Gnomonic standard coordinates: the target is atan(|(xi, eta)|) from the centre: 500" here.
  const auto run = visors::test::run_tool(
      "sun", std::string(R"({"time":"2024-10-01T12:00:00","target_offset_arcsec":[300,-400],)") + kState + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const double expected = std::atan(500.0 / kRadToArcsec) * kRadToArcsec;
  EXPECT_NEAR(angle_arcsec(vec(run.json()["target_unit_gcrf"]), vec(run.json()["apparent_unit_gcrf"])), expected, 1e-6);
}

TEST(ToolSun, NoTargetWithoutItsOffset) {
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2024-10-01T12:00:00",)") + kState + "}");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_FALSE(run.json().contains("target_unit_gcrf"));
}

TEST(ToolSun, BadTimeNamesTheField) {
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2024-13-01T00:00:00",)") + kState + "}");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("time"), std::string::npos) << run.err;
}

TEST(ToolSun, TimeOutsideTheEphemerisNamesTheField) {
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2150-01-01T00:00:00",)") + kState + "}");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("time: must be within 1900-2099"), std::string::npos) << run.err;
}

TEST(ToolSun, ImpossibleVelocityNamesTheField) {
  const auto run = visors::test::run_tool("sun", R"({"time":"2024-10-01T00:00:00","r_gcrf":[7e6,0,0],"v_gcrf":[0,3e8,0]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("v_gcrf"), std::string::npos) << run.err;
}

TEST(ToolSun, MissingVelocityNamesTheField) {
  const auto run = visors::test::run_tool("sun", R"({"time":"2024-10-01T00:00:00","r_gcrf":[7e6,0,0]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("v_gcrf"), std::string::npos) << run.err;
}

TEST(ToolSun, OffsetOfWrongSizeNamesTheField) {
  const auto run = visors::test::run_tool(
      "sun", std::string(R"({"time":"2024-10-01T12:00:00","target_offset_arcsec":[1,2,3],)") + kState + "}");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("target_offset_arcsec"), std::string::npos) << run.err;
}

TEST(ToolSun, UnknownKeyIsRefused) {
  const auto run = visors::test::run_tool("sun", std::string(R"({"time":"2024-10-01T12:00:00","epoch":1,)") + kState + "}");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("epoch"), std::string::npos) << run.err;
}

}  // namespace
