// `visors tool safety` through the real binary.
#include <gtest/gtest.h>

#include <string>

#include "apps/mission_input.hpp"
#include "apps/run_tool.hpp"

namespace {

using visors::test::with_mission_chief;

// Mission standby orbit a*[0,0,0,200,0,200] m: parallel e/i vectors, RN minimum ~200 m
// (199.2 m with the eccentric map and J2, tests/safety/test_passive_safety.cpp), safe.
TEST(ToolSafety, StandbyOrbitIsSafe) {
  const auto run = visors::test::run_tool(
      "safety", with_mission_chief(R"(,"roe":[0,0,0,200,0,200],"horizon":8515.5,"plane":"rn","q":3})"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_NEAR(out["min_separation"].get<double>(), 200.0, 1.5);
  EXPECT_EQ(out["min_separation_margin"].get<double>(), out["min_separation"].get<double>());  // no cov
  EXPECT_TRUE(out["safe"].get<bool>());
  EXPECT_GE(out["t_min"].get<double>(), 0.0);
}

// Perpendicular e/i vectors with 1 m^2 on every a*ROE: unsafe in the RN plane (radial and normal
// separations vanish together), margin below the separation. In 3D the 50 m along-track offset
// keeps it safe over the horizon.
TEST(ToolSafety, PerpendicularEiWithCovarianceIsUnsafe) {
  const auto run = visors::test::run_tool(
      "safety", with_mission_chief(R"(,"roe":[0,50,0,100,100,0],"horizon":8515.5,"plane":"rn","q":3,"epsilon":5,)"
                      R"("cov":[[1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]})"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_FALSE(out["safe"].get<bool>());
  EXPECT_LT(out["min_separation_margin"].get<double>(), out["min_separation"].get<double>());
}

TEST(ToolSafety, NonPsdCovarianceExitCode2NamesCov) {
  const auto run = visors::test::run_tool(
      "safety", with_mission_chief(R"(,"roe":[0,0,0,200,0,200],"horizon":8515.5,"plane":"rn","q":3,)"
                      R"("cov":[[-1,0,0,0,0,0],[0,1,0,0,0,0],[0,0,1,0,0,0],[0,0,0,1,0,0],[0,0,0,0,1,0],[0,0,0,0,0,1]]})"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("cov"), std::string::npos) << run.err;
}

TEST(ToolSafety, BadPlaneAndShortRoeNamed) {
  auto run = visors::test::run_tool("safety", with_mission_chief(R"(,"roe":[0,0,0,200,0,200],"horizon":100,"plane":"xy","q":3})"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("plane"), std::string::npos) << run.err;
  run = visors::test::run_tool("safety", with_mission_chief(R"(,"roe":[0,0,0,200,0],"horizon":100,"plane":"rn","q":3})"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("roe"), std::string::npos) << run.err;
  run = visors::test::run_tool("safety", with_mission_chief(R"(,"roe":[0,0,0,200,0,200],"horizon":-1,"plane":"rn","q":3})"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("horizon"), std::string::npos) << run.err;
}

}  // namespace
