// `visors tool klobuchar` through the real binary.
#include <gtest/gtest.h>

#include <string>

#include "apps/run_tool.hpp"

namespace {

// Broadcast coefficients of brdc1820.10n (2010-07-01; the header's ION ALPHA / ION BETA).
constexpr char kCoefficients[] =
    R"("alpha":[0.4657e-08,0.1490e-07,-0.5960e-07,-0.1192e-06],"beta":[0.8192e+05,0.8192e+05,-0.6554e+05,-0.5243e+06])";

// Zenith at the equator and Greenwich, 12:00 GPS: IS-GPS-200 Figure 20-4 evaluated in Python
// (tests/gnss/test_klobuchar.cpp) gives 2.778845759341267 m.
TEST(ToolKlobuchar, ZenithAtNoonMatchesTheDocumentEvaluation) {
  const auto run = visors::test::run_tool(
      "klobuchar", std::string("{") + kCoefficients + R"(,"gps_time":"2010-07-01T12:00:00","lat":0,"lon":0,"az":0,"el":1.5707963267948966})");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  // the same formula in doubles (Python, comment above); loose: measured 0 (2026-11), bound 1e-12 m ~2000x above round-off (ulp 4.4e-16 m)
  EXPECT_NEAR(run.json()["delay_m"].get<double>(), 2.778845759341267, 1e-12);
}

TEST(ToolKlobuchar, ThreeAlphasAreRejectedByName) {
  const auto run = visors::test::run_tool(
      "klobuchar", R"({"alpha":[1,2,3],"beta":[0,0,0,0],"gps_time":"2010-07-01T12:00:00","lat":0,"lon":0,"az":0,"el":1})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("alpha"), std::string::npos);
}

TEST(ToolKlobuchar, NegativeElevationIsRejectedByName) {
  const auto run = visors::test::run_tool(
      "klobuchar", std::string("{") + kCoefficients + R"(,"gps_time":"2010-07-01T12:00:00","lat":0,"lon":0,"az":0,"el":-0.2})");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("el:"), std::string::npos);
}

}  // namespace
