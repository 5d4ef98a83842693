#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/host_clock.hpp"

namespace {

using visors::sim::HostClock;
using visors::sim::HostClockSettings;
using visors::sim::RandomStream;

HostClock make_clock(const HostClockSettings& settings, std::uint64_t seed = 5) {
  auto clock = HostClock::create(settings, RandomStream(seed, "test.clock"));
  EXPECT_TRUE(clock.ok());
  return std::move(clock).value();
}

// Disciplined by the PPS, the offset is N(0, pps_sigma) afresh each tone: the RMS of 40,000
// tones is sigma within 0.35 % (1 sigma of a sample RMS: 1 / sqrt(2 N)); 2 % allowed.
TEST(HostClock, DisciplinedOffsetHasThePpsSigma) {
  HostClockSettings s;
  s.pps_sigma_s = 20e-9;
  HostClock clock = make_clock(s);
  double sum = 0.0;
  const int n = 40000;
  for (int k = 0; k < n; ++k) {
    clock.tone(k, true);
    sum += clock.offset_s() * clock.offset_s();
  }
  EXPECT_NEAR(std::sqrt(sum / n), 20e-9, 0.02 * 20e-9);
}

// Free-running, the offset grows linearly at the oscillator's frequency error from the last
// disciplined value: after 300 s, offset = offset_0 + y * 300 s (to rounding).
TEST(HostClock, FreeRunningOffsetGrowsAtTheFrequencyError) {
  HostClock clock = make_clock(HostClockSettings{});
  clock.tone(0.0, true);
  const double offset_0 = clock.offset_s();
  for (int k = 1; k <= 300; ++k) clock.tone(k, false);
  EXPECT_NEAR(clock.offset_s(), offset_0 + clock.frequency_error() * 300.0, 1e-15);
}

// The frequency error is drawn per run: not zero with the default sigma, and zero without one.
TEST(HostClock, FrequencyErrorIsDrawnFromItsSigma) {
  EXPECT_NE(make_clock(HostClockSettings{}).frequency_error(), 0.0);
  HostClockSettings s;
  s.oscillator_sigma = 0.0;
  EXPECT_EQ(make_clock(s).frequency_error(), 0.0);
}

// A solution again resets the offset to the PPS error (the drift does not carry over).
TEST(HostClock, SolutionAgainResynchronises) {
  HostClockSettings s;
  s.pps_sigma_s = 0.0;
  s.oscillator_sigma = 1e-5;
  HostClock clock = make_clock(s);
  clock.tone(0.0, true);
  for (int k = 1; k <= 100; ++k) clock.tone(k, false);
  ASSERT_NE(clock.offset_s(), 0.0);
  clock.tone(101.0, true);
  EXPECT_EQ(clock.offset_s(), 0.0);
  EXPECT_NEAR(clock.max_abs_offset_s(), std::abs(clock.frequency_error()) * 100.0, 1e-15);
}

TEST(HostClockSettings, NegativePpsSigmaNamesTheField) {
  HostClockSettings s;
  s.pps_sigma_s = -1.0;
  EXPECT_EQ(s.validate().error().field, "pps_sigma_ns");
}

TEST(HostClockScenario, KeysAreReadInNanosecondsAndPpm) {
  auto s = visors::sim::campaign_from_toml("[clock]\npps_sigma_ns = 50\noscillator_sigma_ppm = 2\n");
  ASSERT_TRUE(s.ok()) << s.error().describe();
  EXPECT_DOUBLE_EQ(s->host_clock.pps_sigma_s, 50e-9);
  EXPECT_DOUBLE_EQ(s->host_clock.oscillator_sigma, 2e-6);
}

TEST(HostClockScenario, OutOfRangeNamesTheKey) {
  auto s = visors::sim::campaign_from_toml("[clock]\noscillator_sigma_ppm = 5000\n");
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().field, "clock.oscillator_sigma_ppm");
}

}  // namespace
