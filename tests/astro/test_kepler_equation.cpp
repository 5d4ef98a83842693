// Kepler's equation and anomaly conversions.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "visors/astro/kepler_equation.hpp"
#include "visors/core/constants.hpp"

namespace {
using namespace visors::astro;
using visors::core::kPi;

// Property (definition): E - e sin E = M; residual at round-off for e up to 0.99, including the
// hard corner M -> 0 with e -> 1 and M near pi.
TEST(KeplerEquation, ResidualAtRoundOffOverGrid) {
  const std::vector<double> eccentricities{0.0, 1e-6, 0.004, 0.1, 0.5, 0.7, 0.9, 0.97, 0.99};
  const std::vector<double> means{0.0,  1e-12, 1e-8,  1e-4,       0.01,        0.3, 1.0, 2.0,
                                  3.0, kPi - 1e-6, kPi, -1e-9, -2.5, 7.0, -20.0, 100.0};
  double worst = 0.0;
  for (double e : eccentricities) {
    for (double m : means) {
      const double ecc = eccentric_from_mean(m, e);
      worst = std::max(worst, std::abs(ecc - e * std::sin(ecc) - m) / std::max(1.0, std::abs(m)));
    }
  }
  EXPECT_LT(worst, 2e-15);
}

// Property: the relative residual stays at round-off for tiny M with e = 0.99 (E ~ M/(1-e)).
TEST(KeplerEquation, TinyMeanAnomalyHighEccentricityRelativeResidual) {
  const double e = 0.99;
  const double m = 1e-10;
  const double ecc = eccentric_from_mean(m, e);
  // E - e sin E evaluated stably: (1-e) E + e (E - sin E), E - sin E ~ E^3/6.
  const double lhs = (1.0 - e) * ecc + e * ecc * ecc * ecc / 6.0;
  // loose: measured 1.1e-16 (2026-11), bound 1e-13 ~900x above round-off
  EXPECT_NEAR(lhs / m, 1.0, 1e-13);
}

// Property: the revolution count is kept (E - M is bounded by e).
TEST(KeplerEquation, KeepsRevolutionCount) {
  const double m = 20.0 * kPi + 0.3;
  EXPECT_LE(std::abs(eccentric_from_mean(m, 0.5) - m), 0.5);
}

// Property: mean -> true -> mean is the identity.
TEST(KeplerEquation, MeanTrueRoundTrip) {
  double worst = 0.0;
  for (double e : {0.0, 1e-6, 0.004, 0.7, 0.99}) {
    for (double m = -7.0; m < 7.0; m += 0.37) {
      worst = std::max(worst, std::abs(mean_from_true(true_from_mean(m, e), e) - m));
    }
  }
  // loose: measured 7.6e-15 rad (2026-11), bound 1e-12 ~130x above
  EXPECT_LT(worst, 1e-12);
}

// Reference: Vallado, Fundamentals of Astrodynamics 4th ed., Example 2-1: M = 235.4 deg,
// e = 0.4 -> E = 220.512074767522 deg.
TEST(KeplerEquation, ValladoExample2_1) {
  const double ecc = eccentric_from_mean(235.4 * visors::core::kDegToRad, 0.4);
  // loose: the book prints 1e-12 deg; measured 8.5e-14 deg (2026-11), bound 1e-9 ~1e4x above
  EXPECT_NEAR(ecc / visors::core::kDegToRad, 220.512074767522, 1e-9);
}

// Property: true anomaly from eccentric anomaly agrees with the half-angle formula.
TEST(KeplerEquation, TrueAnomalyMatchesHalfAngleFormula) {
  const double e = 0.7;
  const double ecc = 1.1;
  const double expected = 2.0 * std::atan(std::sqrt((1 + e) / (1 - e)) * std::tan(ecc / 2.0));
  // round-off (ulp(pi) 4.4e-16); measured 0 (2026-11)
  EXPECT_NEAR(true_from_eccentric(ecc, e), expected, 1e-14);
}

TEST(KeplerEquation, RejectsEccentricityOne) {
  const auto r = solve_kepler(1.0, 1.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "e");
}

TEST(KeplerEquation, RejectsNegativeEccentricity) {
  EXPECT_EQ(solve_kepler(1.0, -0.1).error().field, "e");
}

TEST(KeplerEquation, RejectsNonFiniteMeanAnomaly) {
  EXPECT_EQ(solve_kepler(std::nan(""), 0.1).error().field, "M");
}

}  // namespace
