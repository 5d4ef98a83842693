// `visors tool roe` through the real binary.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/run_tool.hpp"

namespace {

// Property (definition, docs/conventions.md): a deputy differing only by RAAN 1e-5 rad has
// dlambda = 1e-5 cos i_c, diy = 1e-5 sin i_c.
TEST(ToolRoe, RaanOffsetDefinition) {
  const auto run = visors::test::run_tool("roe", R"({
    "chief": {"a":6878136.3,"e":0.004,"i":1.7069,"raan":2.0,"argp":1.5708,"M":0.0},
    "deputy":{"a":6878136.3,"e":0.004,"i":1.7069,"raan":2.00001,"argp":1.5708,"M":0.0}})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto roe = run.json()["roe"];
  ASSERT_EQ(roe.size(), 6u);
  // round-off of RAAN_d - RAAN_c (ulp(2 rad) 4.4e-16 rad); measured 3.0e-17, 6.5e-17 (2026-11)
  EXPECT_NEAR(roe[1].get<double>(), 1e-5 * std::cos(1.7069), 1e-15);
  EXPECT_NEAR(roe[5].get<double>(), 1e-5 * std::sin(1.7069), 1e-15);
}

TEST(ToolRoe, DaIsRelative) {
  const auto run = visors::test::run_tool("roe", R"({
    "chief": {"a":7000000,"e":0.0,"i":1.0,"raan":0,"argp":0,"M":0},
    "deputy":{"a":7000070,"e":0.0,"i":1.0,"raan":0,"argp":0,"M":0}})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // 70 m / 7e6 m, one rounded division; loose: measured 0 (2026-11), bound 1e-17 ~6000x above round-off (ulp(1e-5) 1.7e-21)
  EXPECT_NEAR(run.json()["roe"][0].get<double>(), 1e-5, 1e-17);
}

TEST(ToolRoe, BadDeputyEccentricityExitCode2NamesField) {
  const auto run = visors::test::run_tool("roe", R"({
    "chief": {"a":7e6,"e":0.0,"i":1.0,"raan":0,"argp":0,"M":0},
    "deputy":{"a":7e6,"e":1.0,"i":1.0,"raan":0,"argp":0,"M":0}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("deputy.e"), std::string::npos) << run.err;
}

TEST(ToolRoe, MissingChiefFieldNamed) {
  const auto run = visors::test::run_tool("roe", R"({
    "chief": {"a":7e6,"e":0.0,"i":1.0,"raan":0,"argp":0},
    "deputy":{"a":7e6,"e":0.0,"i":1.0,"raan":0,"argp":0,"M":0}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("chief.M"), std::string::npos) << run.err;
}

}  // namespace
