// `visors tool conic` through the real binary.
#include <gtest/gtest.h>

#include <cmath>

#include "apps/run_tool.hpp"

namespace {

// min x1 + x2 s.t. x1 >= 1, x2 >= 2: both bounds active, x = (1, 2), objective 3, z = (1, 1)
// (stationarity c + G'z = 0 with G = -I).
TEST(ToolConic, TinyLp) {
  const auto run = visors::test::run_tool(
      "conic", R"({"c":[1,1],"G":[[-1,0],[0,-1]],"h":[-1,-2],"dims":{"l":2,"q":[]}})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_EQ(out["status"], "optimal");
  // 10x the solver's stopping tolerances 1e-8 (conic_settings.hpp); loose: measured 0 (2026-11), bound 1e-7 ~2e8x above round-off
  EXPECT_NEAR(out["primal_objective"].get<double>(), 3.0, 1e-7);
  EXPECT_NEAR(out["x"][1].get<double>(), 2.0, 1e-7);
  EXPECT_NEAR(out["z"][0].get<double>(), 1.0, 1e-7);
  EXPECT_EQ(out["y"].size(), 0u);
  EXPECT_GE(out["iterations"].get<int>(), 1);
}

// Distance from a = (0, 3, 4) to Q^3 is sqrt(12.5): the projection ((a0 + ||a1||)/2)(1, a1/||a1||)
// = (2.5, 1.5, 2) (Bauschke & Combettes 2017, ex. 29.11). Variables (x, t); cones (t, x - a), x.
TEST(ToolConic, SecondOrderConeProjectionDistance) {
  const auto run = visors::test::run_tool(
      "conic",
      R"({"c":[0,0,0,1],"G":[[0,0,0,-1],[-1,0,0,0],[0,-1,0,0],[0,0,-1,0],[-1,0,0,0],[0,-1,0,0],[0,0,-1,0]],)"
      R"("h":[0,0,-3,-4,0,0,0],"dims":{"l":0,"q":[4,3]},"A":[],"b":[]})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.json()["status"], "optimal");
  // 10x the solver's stopping tolerances 1e-8 (conic_settings.hpp); measured 5.5e-9 (2026-11)
  EXPECT_NEAR(run.json()["primal_objective"].get<double>(), std::sqrt(12.5), 1e-7);
}

// min 1/2 (x1^2 + x2^2) s.t. x1 + x2 = 2 (x1 <= 10 inactive): by symmetry x = (1, 1), objective 1,
// and Px + A'y = 0 gives y = -1.
TEST(ToolConic, EqualityConstrainedQp) {
  const auto run = visors::test::run_tool(
      "conic", R"({"c":[0,0],"P":[[1,0],[0,1]],"A":[[1,1]],"b":[2],"G":[[1,0]],"h":[10],"dims":{"l":1}})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto out = run.json();
  EXPECT_EQ(out["status"], "optimal");
  // the solver's stopping tolerances 1e-8 (conic_settings.hpp), bounds 10x / 100x; loose: measured 0 (objective), 8.2e-11 (x, y) (2026-11), bounds 1e-7 / 1e-6 ~1e4x above
  EXPECT_NEAR(out["primal_objective"].get<double>(), 1.0, 1e-7);
  EXPECT_NEAR(out["x"][0].get<double>(), 1.0, 1e-6);
  EXPECT_NEAR(out["y"][0].get<double>(), -1.0, 1e-6);
}

// x >= 1 and x <= 0 cannot both hold.
TEST(ToolConic, PrimalInfeasibleHasNullObjectives) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1],"G":[[-1],[1]],"h":[-1,0],"dims":{"l":2,"q":[]}})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.json()["status"], "primal_infeasible");
  EXPECT_TRUE(run.json()["primal_objective"].is_null());
}

TEST(ToolConic, GRowCountMismatchNamesG) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1,1],"G":[[-1,0]],"h":[-1,-2],"dims":{"l":2,"q":[]}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("G"), std::string::npos) << run.err;
}

TEST(ToolConic, ZeroConeDimensionNamed) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1],"G":[],"h":[],"dims":{"l":0,"q":[0]}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("dims.q[0]"), std::string::npos) << run.err;
}

TEST(ToolConic, NonNumericEntryNamed) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1],"G":[[-1]],"h":["x"],"dims":{"l":1}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("h[0]"), std::string::npos) << run.err;
}

TEST(ToolConic, AsymmetricPNamed) {
  const auto run = visors::test::run_tool(
      "conic", R"({"c":[0,0],"P":[[1,0.5],[0,1]],"G":[[1,0]],"h":[10],"dims":{"l":1}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("P"), std::string::npos) << run.err;
}

TEST(ToolConic, MissingBWithANamed) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1],"A":[[1]],"G":[[-1]],"h":[0],"dims":{"l":1}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("b"), std::string::npos) << run.err;
}

TEST(ToolConic, UnknownKeyRejected) {
  const auto run = visors::test::run_tool("conic", R"({"c":[1],"G":[[-1]],"h":[0],"dims":{"l":1},"Q":[]})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("Q"), std::string::npos) << run.err;
}

}  // namespace
