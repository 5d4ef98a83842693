// Ideal navigation: the errors have the configured size and correlation, the covariance floor.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/sim/ideal_navigation.hpp"

namespace {

using visors::sim::IdealNavigation;
using visors::sim::NavigationErrorSettings;
using visors::sim::RandomStream;

const visors::core::GpsTime kT0 = visors::core::GpsTime::from_seconds(1.4e9);

visors::core::StateVector chief() {
  return visors::astro::cartesian_from_keplerian({6878136.3, 0.004, 1.7, 2.7, 1.57, 0.0}, 3.986004415e14);
}

// Stationary Gauss-Markov: the sample variance of the relative position error over many
// correlation times is the configured (3D) sigma^2 / 3 per axis; 2000 samples 60 s apart with
// tau = 60 s are ~1,500 effectively independent ones, a 5-sigma band of the variance estimate of
// 5 * sqrt(2 / 1500) = 18 %.
TEST(IdealNavigation, RelativePositionErrorHasTheConfiguredSigma) {
  NavigationErrorSettings settings;
  settings.correlation_time_s = 60.0;
  IdealNavigation nav(settings, RandomStream(5, "nav"));
  const auto c = chief();
  const auto d = visors::core::deputy_state_gcrf(c, {Eigen::Vector3d(0, 40, 0), Eigen::Vector3d::Zero()});
  double sum2 = 0.0;
  constexpr int kN = 2000;
  for (int k = 0; k < kN; ++k) {
    const auto sol = nav.solve(kT0 + 60.0 * k, c, d, k == 0 ? 0.0 : 60.0);
    const auto rel = visors::core::relative_state_rtn(sol.chief_gcrf, sol.deputy_gcrf);
    sum2 += (rel.dr_rtn - Eigen::Vector3d(0, 40, 0)).squaredNorm();
  }
  EXPECT_NEAR(std::sqrt(sum2 / kN), settings.relative_position_m, 0.09 * settings.relative_position_m);
}

// One second apart with tau = 600 s the error barely moves: the correlation exp(-1/600).
TEST(IdealNavigation, ErrorsAreCorrelatedInTime) {
  IdealNavigation nav(NavigationErrorSettings{}, RandomStream(6, "nav"));
  const auto c = chief();
  const auto a = nav.solve(kT0, c, c, 0.0);
  const auto b = nav.solve(kT0 + 1.0, c, c, 1.0);
  // Gauss-Markov step: 3D sigma sqrt(2 (1 - exp(-1/600))) = 0.58 mm for the 1 cm default (ideal_navigation.cpp), bound 2 mm ~3.5x that; measured 0.41 mm (2026-11)
  EXPECT_LT((a.deputy_gcrf.r - a.chief_gcrf.r - (b.deputy_gcrf.r - b.chief_gcrf.r)).norm(), 2e-3);
}

// A zero sigma reports the floor (1 mm, 1 um/s per axis), never a zero covariance.
TEST(IdealNavigation, ZeroSigmaReportsTheCovarianceFloor) {
  NavigationErrorSettings settings{0.0, 0.0, 0.0, 0.0, 600.0};
  IdealNavigation nav(settings, RandomStream(7, "nav"));
  const auto sol = nav.solve(kT0, chief(), chief(), 0.0);
  EXPECT_DOUBLE_EQ(sol.relative_covariance_rtn(0, 0), 1e-6);
}

TEST(IdealNavigation, ZeroSigmaIsTheTruth) {
  NavigationErrorSettings settings{0.0, 0.0, 0.0, 0.0, 600.0};
  IdealNavigation nav(settings, RandomStream(7, "nav"));
  const auto c = chief();
  const auto sol = nav.solve(kT0, c, c, 0.0);
  // zero sigma adds a zero error, round-off at 7e6 m (ulp 9.3e-10 m); measured 0 (2026-11)
  EXPECT_LT((sol.chief_gcrf.r - c.r).norm(), 1e-9);
}

}  // namespace
