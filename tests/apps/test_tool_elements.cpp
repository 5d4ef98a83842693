// `visors tool elements` through the real binary.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/run_tool.hpp"

namespace {

// Reference: Vallado 4th ed., Example 2-5 (mu = 398600.4418 km^3/s^2): e = 0.832853,
// i = 87.870 deg.
TEST(ToolElements, StateToElementsValladoExample2_5) {
  const auto run = visors::test::run_tool(
      "elements",
      R"({"r":[6524834.0,6862875.0,6448296.0],"v":[4901.327,5533.756,-1976.341],"mu":3.986004418e14})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // Vallado prints e to 6 decimals; measured 4.0e-7 (2026-11). i printed to 3 decimals: measured regression bound: 8.7e-4 deg (2026-11); bound 2e-3 deg
  EXPECT_NEAR(run.json()["e"].get<double>(), 0.832853, 1e-6);
  EXPECT_NEAR(run.json()["i"].get<double>() * 180.0 / M_PI, 87.870, 2e-3);
}

// Property: u = argp + M (mean argument of latitude, wrapped) and nu are reported.
TEST(ToolElements, ReportsTrueAnomalyAndArgumentOfLatitude) {
  const auto run = visors::test::run_tool("elements", R"({"a":7e6,"e":0.0,"i":1.0,"raan":0.5,"argp":0.0,"M":0.3})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto back = visors::test::run_tool("elements", "{\"r\":" + run.json()["r"].dump() + ",\"v\":" + run.json()["v"].dump() + "}");
  ASSERT_EQ(back.exit_code, 0) << back.err;
  // JSON round trip of 17 digits, round-off; loose: measured 1.7e-16 rad (2026-11), bound 1e-12 rad ~6000x above
  EXPECT_NEAR(back.json()["u"].get<double>(), 0.3, 1e-12);
  EXPECT_NEAR(back.json()["nu"].get<double>(), 0.3, 1e-12);
}

// Property: elements -> state -> elements round trip through the binary (17 significant digits).
TEST(ToolElements, RoundTrip) {
  const auto run = visors::test::run_tool("elements", R"({"a":6878136.3,"e":0.004,"i":1.7069,"raan":2.7489,"argp":1.5708,"M":0.7})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto back = visors::test::run_tool("elements", "{\"r\":" + run.json()["r"].dump() + ",\"v\":" + run.json()["v"].dump() + "}");
  // round trip of 17 digits, round-off (ulp(a) 9.3e-10 m); loose: measured 2.8e-9 m (2026-11), bound 1e-6 m ~360x above
  EXPECT_NEAR(back.json()["a"].get<double>(), 6878136.3, 1e-6);
}

TEST(ToolElements, BadEccentricityExitCode2NamesField) {
  const auto run = visors::test::run_tool("elements", R"({"a":7e6,"e":1.5,"i":1.0,"raan":0,"argp":0,"M":0})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("e:"), std::string::npos) << run.err;
}

TEST(ToolElements, BothFormsRejected) {
  const auto run = visors::test::run_tool("elements", R"({"a":7e6,"r":[7e6,0,0],"v":[0,7e3,0]})");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(ToolElements, UnknownKeyRejectedAndNamed) {
  const auto run = visors::test::run_tool("elements", R"({"r":[7e6,0,0],"v":[0,7e3,0],"muu":1})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("muu"), std::string::npos) << run.err;
}

TEST(ToolElements, HyperbolicStateRejectedNamingV) {
  const auto run = visors::test::run_tool("elements", R"({"r":[7e6,0,0],"v":[0,12e3,0]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("v:"), std::string::npos) << run.err;
}

}  // namespace
