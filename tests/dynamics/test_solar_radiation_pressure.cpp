// Solar radiation pressure and the cylindrical shadow.

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "visors/dynamics/solar_radiation_pressure.hpp"

namespace visors::dynamics {
namespace {

constexpr double kEarthRadius = 6378136.3;  // [m]

// brahe solar_radiation_pressure.rs test_accel_solar_radiation_pressure (M&G eq. 3.75 in closed
// form; docs/algorithms/dynamics.md#solar-radiation-pressure):
// satellite at 1 AU on +x, Sun at the origin, A/m = 1, Cr = 1, P = 4.5e-6 -> (+4.5e-6, 0, 0).
TEST(SolarRadiationPressure, OneAstronomicalUnitReferenceCase) {
  const Eigen::Vector3d a = srp_acceleration({kAstronomicalUnit, 0, 0}, Eigen::Vector3d::Zero(), 1.0,
                                             4.5e-6, 1.0, 1.0, 1.0);
  // round-off (ulp(4.5e-6) = 8.5e-22); measured 8.5e-22 (2026-11)
  EXPECT_NEAR(a.x(), 4.5e-6, 1e-20);
  EXPECT_EQ(a.y(), 0.0);
  EXPECT_EQ(a.z(), 0.0);
}

// Inverse-square law: at half the distance the pressure is four times larger (M&G eq. 3.75).
TEST(SolarRadiationPressure, ScalesWithInverseSquareOfSunDistance) {
  const Eigen::Vector3d sun(0, 0, 0);
  const double a1 = srp_acceleration({kAstronomicalUnit, 0, 0}, sun, 1.0, 4.56e-6, 1.8, 0.35, 11.35).norm();
  const double a2 = srp_acceleration({0.5 * kAstronomicalUnit, 0, 0}, sun, 1.0, 4.56e-6, 1.8, 0.35, 11.35).norm();
  // round-off; measured 0 (2026-11)
  EXPECT_NEAR(a2 / a1, 4.0, 1e-12);
}

// The mission spacecraft (DSC: Cr 1.8, 0.35 m^2, 11.35 kg) feel 4.56e-6*1.8*0.35/11.35 = 2.53e-7
// m/s^2 away from the Sun near the Earth.
TEST(SolarRadiationPressure, PointsAwayFromTheSun) {
  const Eigen::Vector3d sun(kAstronomicalUnit, 0, 0);
  const Eigen::Vector3d r(0, 7e6, 0);
  const Eigen::Vector3d a = srp_acceleration(r, sun, 1.0, kSolarPressureAt1Au, 1.8, 0.35, 11.35);
  EXPECT_LT(a.dot(sun - r), 0.0);
  // loose: measured 5.5e-16 m/s^2 (2026-11; the 7000 km offset changes the Sun distance by 1e-9 relative), bound 1e-10 ~2e5x above
  EXPECT_NEAR(a.norm(), 4.56e-6 * 1.8 * 0.35 / 11.35, 1e-10);
}

TEST(CylindricalShadow, SunlitOnTheDaySide) {
  EXPECT_EQ(cylindrical_shadow({7e6, 0, 0}, {kAstronomicalUnit, 0, 0}, kEarthRadius), 1.0);
}

TEST(CylindricalShadow, DarkBehindTheEarth) {
  EXPECT_EQ(cylindrical_shadow({-7e6, 0, 0}, {kAstronomicalUnit, 0, 0}, kEarthRadius), 0.0);
}

// Behind the terminator plane but outside the cylinder (a 500 km orbit over the pole at
// the terminator: 6878 km from the axis > R_E).
TEST(CylindricalShadow, SunlitOutsideTheCylinderOnTheNightSide) {
  EXPECT_EQ(cylindrical_shadow({-1e6, 0, 6.878e6}, {kAstronomicalUnit, 0, 0}, kEarthRadius), 1.0);
}

// The shadow boundary is the cylinder |r - (r.e)e| = R_E.
TEST(CylindricalShadow, BoundaryIsTheEarthRadiusCylinder) {
  const Eigen::Vector3d sun(kAstronomicalUnit, 0, 0);
  EXPECT_EQ(cylindrical_shadow({-7e6, 0, kEarthRadius - 1.0}, sun, kEarthRadius), 0.0);
  EXPECT_EQ(cylindrical_shadow({-7e6, 0, kEarthRadius + 1.0}, sun, kEarthRadius), 1.0);
}

// --- Conical shadow (Montenbruck & Gill 2000, sec. 3.4.2) ---

TEST(ConicalShadow, FullSunOnTheDaySide) {
  EXPECT_EQ(conical_shadow({7e6, 0, 0}, {kAstronomicalUnit, 0, 0}, kEarthRadius), 1.0);
}

TEST(ConicalShadow, UmbraBehindTheEarth) {
  EXPECT_EQ(conical_shadow({-7e6, 0, 0}, {kAstronomicalUnit, 0, 0}, kEarthRadius), 0.0);
}

// Where the cylindrical boundary lies (|r_perp| = R_E, apparent separation c = Earth's apparent
// radius b), the Sun's disk is centred on the Earth's limb: about half of it is visible (a bit
// less, since the limb curves around the small solar disk).
TEST(ConicalShadow, HalfTheSunAtTheCylindricalBoundary) {
  const double nu = conical_shadow({-7e6, 0, kEarthRadius}, {kAstronomicalUnit, 0, 0}, kEarthRadius);
  // "a bit less" than 0.5 (comment above); measured 5.2e-3 below 0.5 (2026-11), bound 0.01
  EXPECT_NEAR(nu, 0.5, 0.01);
}

// Circular 500 km orbit in the ecliptic plane through the shadow: the apparent separation c of
// the Sun and the Earth's centre changes at the orbital rate n, so the penumbra (c from b + a to
// b - a) lasts 2a/n = 8.4 s with a = asin(R_sun / 1 AU); nu falls monotonically through it.
TEST(ConicalShadow, PenumbraLastsTwiceTheSolarRadiusOverTheOrbitalRate) {
  const double radius = kEarthRadius + 500e3;
  const double n = std::sqrt(3.986004415e14 / (radius * radius * radius));
  const Eigen::Vector3d sun(kAstronomicalUnit, 0, 0);
  double entered = -1.0;
  double left = -1.0;
  double previous = 1.0;
  bool monotonic = true;
  for (double t = 0.0; t < 1800.0; t += 1e-3) {
    const double u = 0.5 * std::numbers::pi + n * t;  // from the terminator into the night side
    const double nu = conical_shadow({radius * std::cos(u), radius * std::sin(u), 0.0}, sun, kEarthRadius);
    if (entered < 0.0 && nu < 1.0) entered = t;
    if (left < 0.0 && nu == 0.0) left = t;
    monotonic = monotonic && nu <= previous;
    previous = nu;
  }
  const double expected = 2.0 * std::asin(kSunRadius / kAstronomicalUnit) / n;
  // analytic 2a/n = 8.4 s above; measured 2.3e-4 s off (2026-11), bound 0.01 s
  EXPECT_NEAR(left - entered, expected, 0.01);
  EXPECT_TRUE(monotonic);
}

}  // namespace
}  // namespace visors::dynamics
