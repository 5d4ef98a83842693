// The SD carrier multipath states (nav/sd_multipath.hpp) against the first-order Gauss-Markov
// process they model: stationary variance sigma^2, autocovariance sigma^2 exp(-|dt| / tau)
// (Brown & Hwang, Introduction to Random Signals and Applied Kalman Filtering, the first-order
// Gauss-Markov process), and their life with the SDCP slots.
#include "visors/nav/sd_multipath.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace visors::nav {
namespace {

constexpr double kSigmaZenith = 0.00283;  // [m], the SD of two 2 mm receivers
constexpr double kTau = 60.0;             // [s]

struct Fixture {
  NavVector x = NavVector::Zero();
  NavMatrix P = NavMatrix::Identity();
  AmbiguitySlotBank sdcp = AmbiguitySlotBank::create(state::kSdcpAmbiguities).value();
  SdMultipathStates multipath{kSigmaZenith, kTau};
  int slot = -1;
  int s = -1;

  Fixture() {
    sdcp.release_all(x, P);
    slot = sdcp.acquire(7, 0.0, 1.0, x, P);
    s = SdMultipathStates::state_of(slot);
    multipath.set_elevation_scale(slot, 4.0);  // both antennas at 30 deg: (1/0.25 + 1/0.25) / 2
    multipath.start(slot, x, P);
  }
};

TEST(SdMultipathStates, StateFollowsTheSdcpBank) { EXPECT_EQ(SdMultipathStates::state_of(3), state::kSdcpAmbiguities + 24 + 3); }

// sigma_s^2 = sigma_zenith^2 x 4 at 30 deg: (5.66 mm)^2, in mm^2.
TEST(SdMultipathStates, StartsAtTheSteadyStateVarianceOfItsElevations) {
  const Fixture f;
  EXPECT_NEAR(f.P(f.s, f.s), 4.0 * 2.83 * 2.83, 1e-12);
}

TEST(SdMultipathStates, StartsIndependentOfTheRest) {
  Fixture f;
  f.P(f.s, 0) = f.P(0, f.s) = 0.3;
  f.multipath.start(f.slot, f.x, f.P);
  EXPECT_EQ(f.P.row(f.s).cwiseAbs().sum() - f.P(f.s, f.s), 0.0);
}

TEST(SdMultipathStates, PropagationKeepsTheStationaryVariance) {
  Fixture f;
  const double before = f.P(f.s, f.s);
  f.multipath.propagate(f.sdcp, 7.0, f.x, f.P);
  EXPECT_NEAR(f.P(f.s, f.s), before, 1e-12 * before);
}

// The covariance with a state that does not move (here the slot's ambiguity) decays as the
// autocorrelation exp(-dt / tau).
TEST(SdMultipathStates, PropagationDecaysTheCovarianceAsTheAutocorrelation) {
  Fixture f;
  const int n = state::kSdcpAmbiguities + f.slot;
  f.P(f.s, n) = f.P(n, f.s) = 2.0;
  f.multipath.propagate(f.sdcp, 30.0, f.x, f.P);
  EXPECT_NEAR(f.P(f.s, n), 2.0 * std::exp(-0.5), 1e-14);
}

TEST(SdMultipathStates, PropagationDecaysTheEstimate) {
  Fixture f;
  f.x(f.s) = 4.0;
  f.multipath.propagate(f.sdcp, 60.0, f.x, f.P);
  EXPECT_NEAR(f.x(f.s), 4.0 * std::exp(-1.0), 1e-14);
}

// Two steps of dt equal one of 2 dt (a Markov process's transition and noise compose).
TEST(SdMultipathStates, TwoStepsEqualOne) {
  Fixture a, b;
  a.P(a.s, a.s) = b.P(b.s, b.s) = 1.0;  // away from the steady state, so the noise shows
  a.multipath.propagate(a.sdcp, 5.0, a.x, a.P);
  a.multipath.propagate(a.sdcp, 5.0, a.x, a.P);
  b.multipath.propagate(b.sdcp, 10.0, b.x, b.P);
  EXPECT_NEAR(a.P(a.s, a.s), b.P(b.s, b.s), 1e-12);
}

TEST(SdMultipathStates, AParkedSlotGetsNoProcessNoise) {
  Fixture f;
  (void)f.sdcp.release(f.slot, f.x, f.P);
  SdMultipathStates::park(f.slot, f.x, f.P);
  f.multipath.propagate(f.sdcp, 10.0, f.x, f.P);
  EXPECT_EQ(f.P(f.s, f.s), AmbiguitySlotBank::kParkedVariance);
}

TEST(SdMultipathStates, DisabledItLeavesTheStateParked) {
  Fixture f;
  SdMultipathStates::park(f.slot, f.x, f.P);
  const SdMultipathStates off(0.0, kTau);
  off.start(f.slot, f.x, f.P);
  off.propagate(f.sdcp, 10.0, f.x, f.P);
  EXPECT_EQ(f.P(f.s, f.s), AmbiguitySlotBank::kParkedVariance);
}

}  // namespace
}  // namespace visors::nav
