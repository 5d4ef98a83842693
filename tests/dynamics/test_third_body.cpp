// Third-body point-mass perturbation, checked by two independent methods: the tidal (quadrupole)
// expansion for |r| << |s| and a numerical gradient of the third-body disturbing potential.

#include <cmath>

#include <gtest/gtest.h>

#include "visors/dynamics/third_body.hpp"

namespace visors::dynamics {
namespace {

// The low-precision Moon (M&G sec. 3.3.2) at MJD_TT 60310.25, EME2000, as in brahe's ephemerides.rs
// tests; any realistic lunar position serves here.
const Eigen::Vector3d kMoon(-376313966.331919, 125552784.254334, 80458346.9703463);  // [m]
const Eigen::Vector3d kSatellite(4.0e6, -3.0e6, 4.5e6);                               // |r| ~ 6.7e6 m

// Disturbing potential R = GM (1/|s - r| - r.s/|s|^3) (Montenbruck & Gill 2000, sec. 3.2.1);
// a = grad R.
double disturbing_potential(const Eigen::Vector3d& r, const Eigen::Vector3d& s, double gm) {
  return gm * (1.0 / (s - r).norm() - r.dot(s) / std::pow(s.norm(), 3));
}

TEST(ThirdBody, EqualsGradientOfDisturbingPotential) {
  const Eigen::Vector3d a = third_body_acceleration(kSatellite, kMoon, kGmMoon);
  // [m]: truncation h^2/6 |d3R/dr3| ~ 1e6/6 * 15 GM/s^4 ~ 5e-16 m/s^2; round-off
  // eps GM/|s| / h ~ 2.7e-12 / 2e3 ~ 1.4e-15 m/s^2 (a ~ 1e-6 m/s^2).
  const double h = 1000.0;
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d dr = h * Eigen::Vector3d::Unit(k);
    const double numeric = (disturbing_potential(kSatellite + dr, kMoon, kGmMoon) -
                            disturbing_potential(kSatellite - dr, kMoon, kGmMoon)) / (2.0 * h);
    EXPECT_NEAR(a[k], numeric, 1e-14) << "component " << k;
  }
}

// Quadrupole tidal term a = GM/s^3 (3 (e.r) e - r) with relative error O(|r|/|s|) ~ 1.7 %.
TEST(ThirdBody, MatchesTidalExpansionToFirstOrder) {
  const Eigen::Vector3d a = third_body_acceleration(kSatellite, kMoon, kGmMoon);
  const double s = kMoon.norm();
  const Eigen::Vector3d e = kMoon / s;
  const Eigen::Vector3d tidal = kGmMoon / (s * s * s) * (3.0 * e.dot(kSatellite) * e - kSatellite);
  EXPECT_LT((a - tidal).norm() / tidal.norm(), 3.0 * kSatellite.norm() / s);
}

// The lunar tide at LEO is ~1e-6 m/s^2 (Montenbruck & Gill 2000, Fig. 3.1).
TEST(ThirdBody, LunarTideMagnitudeAtLowEarthOrbit) {
  const double a = third_body_acceleration(kSatellite, kMoon, kGmMoon).norm();
  // M&G Fig. 3.1 (~1e-6 m/s^2, above); measured 6.9e-7 m/s^2 (2026-11)
  EXPECT_GT(a, 3e-7);
  EXPECT_LT(a, 3e-6);
}

// IAU 2009 (Luzum et al. 2011): GM_moon = 4.9028001e12 m^3/s^2.
// IAU 2009 value printed to 1e5 m^3/s^2 (the last digit); measured 4.5e4 (2026-11)
TEST(ThirdBody, LunarGravitationalConstant) { EXPECT_NEAR(kGmMoon, 4.9028001e12, 1e5); }

}  // namespace
}  // namespace visors::dynamics
