#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "visors/sim/crosslink.hpp"

namespace {

using visors::sim::Crosslink;
using visors::sim::CrosslinkSettings;
using visors::sim::RandomStream;

Crosslink<int> make(double drop_probability = 0.0, std::uint64_t seed = 1) {
  CrosslinkSettings s;
  s.drop_probability = drop_probability;
  auto link = Crosslink<int>::create(s, RandomStream(seed, "crosslink.osc_to_dsc"));
  EXPECT_TRUE(link.ok());
  return std::move(link).value();
}

TEST(Crosslink, DefaultSettingsAreValid) { EXPECT_TRUE(CrosslinkSettings{}.validate().ok()); }

TEST(Crosslink, RejectsProbabilityAboveOne) {
  CrosslinkSettings s;
  s.drop_probability = 1.5;
  EXPECT_EQ(Crosslink<int>::create(s, RandomStream(1, "x")).error().field, "drop_probability");
}

TEST(Crosslink, RejectsNegativeDelay) {
  CrosslinkSettings s;
  s.delay_s = -0.1;
  EXPECT_EQ(Crosslink<int>::create(s, RandomStream(1, "x")).error().field, "delay_s");
}

// Delay 0.5 s (the default, Guffanti et al., AAS 23-149, 2023, sec. 5): sent at 10 s, not there at
// the largest double below 10.5 s ...
TEST(Crosslink, NothingBeforeTheDelay) {
  Crosslink<int> link = make();
  link.send(10.0, 1);
  EXPECT_TRUE(link.receive(std::nextafter(10.5, 0.0)).empty());
}

// ... and there at exactly 10.5 s (10 + 0.5 is exact in binary).
TEST(Crosslink, DeliveredExactlyAtTheDelay) {
  Crosslink<int> link = make();
  link.send(10.0, 1);
  EXPECT_EQ(link.receive(10.5), std::vector<int>{1});
}

TEST(Crosslink, DeliveredOnlyOnce) {
  Crosslink<int> link = make();
  link.send(10.0, 1);
  (void)link.receive(11.0);
  EXPECT_TRUE(link.receive(12.0).empty());
}

// Messages come out in send order, also when several are due at once and when a later poll
// collects the rest.
TEST(Crosslink, PreservesSendOrder) {
  Crosslink<int> link = make();
  for (int k = 0; k < 10; ++k) link.send(0.1 * k, k);
  std::vector<int> got = link.receive(0.95);  // due: sent at <= 0.45 s -> 0 .. 4
  const std::vector<int> rest = link.receive(100.0);
  got.insert(got.end(), rest.begin(), rest.end());
  EXPECT_EQ(got, (std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7, 8, 9}));
}

TEST(Crosslink, FirstPollReturnsOnlyDueMessages) {
  Crosslink<int> link = make();
  for (int k = 0; k < 10; ++k) link.send(0.1 * k, k);
  EXPECT_EQ(link.receive(0.95), (std::vector<int>{0, 1, 2, 3, 4}));
}

// Works with any copyable message type.
TEST(Crosslink, CarriesArbitraryMessages) {
  CrosslinkSettings s;
  auto created = Crosslink<std::string>::create(s, RandomStream(1, "x"));
  Crosslink<std::string> link = std::move(created).value();
  link.send(0.0, "nav");
  EXPECT_EQ(link.receive(1.0), std::vector<std::string>{"nav"});
}

// Zero drop probability (the default) loses nothing over 10000 messages.
TEST(Crosslink, ZeroDropLosesNothing) {
  Crosslink<int> link = make(0.0);
  for (int k = 0; k < 10000; ++k) link.send(k, k);
  EXPECT_EQ(link.receive(1e6).size(), 10000U);
}

// Drop rate p = 0.2 over N = 20000 messages: the received fraction is binomial, within
// 5 sqrt(p (1 - p) / N) = 0.0141 of 0.8.
TEST(Crosslink, DropRateMatchesTheProbability) {
  constexpr int kN = 20000;
  Crosslink<int> link = make(0.2);
  for (int k = 0; k < kN; ++k) link.send(k, k);
  const double received = static_cast<double>(link.receive(1e6).size()) / kN;
  EXPECT_NEAR(received, 0.8, 5.0 * std::sqrt(0.2 * 0.8 / kN));
}

TEST(Crosslink, CountsDroppedMessages) {
  Crosslink<int> link = make(1.0);
  for (int k = 0; k < 5; ++k) link.send(k, k);
  EXPECT_EQ(link.dropped_count(), 5U);
}

// Losses depend only on the seed and the sends, not on the polling pattern (header comment).
TEST(Crosslink, LossesIndependentOfPolling) {
  Crosslink<int> a = make(0.3, 9), b = make(0.3, 9);
  std::vector<int> got_a, got_b;
  for (int k = 0; k < 1000; ++k) {
    a.send(k, k);
    b.send(k, k);
    const std::vector<int> step = a.receive(k);  // a polls every second, b once at the end
    got_a.insert(got_a.end(), step.begin(), step.end());
  }
  const std::vector<int> step = a.receive(1e6);
  got_a.insert(got_a.end(), step.begin(), step.end());
  got_b = b.receive(1e6);
  EXPECT_EQ(got_a, got_b);
}

}  // namespace
