// `visors tool buffer` through the binary: the pieces of a large impulse and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "apps/mission_input.hpp"
#include "apps/run_tool.hpp"

namespace {

const std::string kChief = visors::test::mission_chief_json();

// (10, 50, 20) mm/s at 10.62 kg = 0.58 N s: more than 26 pieces of <= 0.022 N s, 46.5 s apart.
TEST(ToolBuffer, SplitsALargeImpulseIntoFeasiblePieces) {
  const auto run = visors::test::run_tool(
      "buffer", "{" + kChief + R"(,"maneuver":{"t":2000,"dv_rtn":[0.01,0.05,0.02]},"mass":10.62})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto pieces = run.json()["pieces"];
  ASSERT_GT(pieces.size(), 26u);
  for (const auto& p : pieces) {
    const auto& dv = p["dv_rtn"];
    const double impulse = 10.62 * std::hypot(dv[0].get<double>(), dv[1].get<double>(), dv[2].get<double>());
    // largest impulse 2.2e-2 N s (docs/conventions.md Propulsion) plus 1e-12 N s round-off of dv x mass; measured at most 0.0213 N s (2026-11)
    EXPECT_LE(impulse, 0.022 + 1e-12);
  }
}

TEST(ToolBuffer, MissingMassIsNamed) {
  const auto run = visors::test::run_tool("buffer", "{" + kChief + R"(,"maneuver":{"t":0,"dv_rtn":[0,0.01,0]}})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("mass"), std::string::npos) << run.err;
}

TEST(ToolBuffer, UnknownManeuverKeyIsNamed) {
  const auto run = visors::test::run_tool(
      "buffer", "{" + kChief + R"(,"maneuver":{"t":0,"dv":[0,0.01,0]},"mass":10})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("maneuver.dv"), std::string::npos) << run.err;
}

}  // namespace
