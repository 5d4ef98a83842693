// ROE definition (docs/conventions.md), exact nonlinear, and its inverse.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/astro/relative_orbital_elements.hpp"
#include "astro_test_support.hpp"
#include "visors/core/constants.hpp"

namespace {
using namespace visors::astro;
using visors::astro::test::kDeg;

RelativeOrbitalElements science_roe(double a) {
  RelativeOrbitalElements roe;
  roe << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;  // a*dROE [m], science ROE (Guffanti et al. 2023, Table 5)
  return roe / a;
}

// Property: chief + ROE -> deputy -> ROE is the identity (1e-12), for several chiefs incl. a
// circular one (where argp_c is the convention 0) and large ROE.
TEST(RelativeOrbitalElements, RoundTripThroughDeputy) {
  double worst = 0.0;
  for (const KeplerianElements& chief :
       {test::visors_chief(30.0), KeplerianElements{7.0e6, 0.0, 28.0 * kDeg, 1.0, 0.0, 4.0},
        KeplerianElements{8.0e6, 0.1, 45.0 * kDeg, 5.0, 2.0, 6.1}}) {
    for (double scale : {1.0, 1e3}) {
      const RelativeOrbitalElements roe = scale * science_roe(chief.a);
      const KeplerianElements deputy = deputy_from_roe(chief, roe).value();
      worst = std::max(worst, (roe_from_keplerian(chief, deputy).value() - roe).cwiseAbs().maxCoeff());
    }
  }
  // loose: measured 6.5e-16 (2026-11), bound 1e-12 ~1500x above round-off
  EXPECT_LT(worst, 1e-12);
}

// Property (definition): da is the relative difference of a.
TEST(RelativeOrbitalElements, DaIsRelativeSemiMajorAxisDifference) {
  const KeplerianElements chief = test::visors_chief();
  KeplerianElements deputy = chief;
  deputy.a += 10.0;
  // round-off of 10 / a (ulp ~2e-22); measured 0 (2026-11)
  EXPECT_NEAR(roe_from_keplerian(chief, deputy).value()[roe::kDa], 10.0 / chief.a, 1e-16);
}

// Property (definition): diy = dRAAN sin i_c and dlambda gets dRAAN cos i_c.
TEST(RelativeOrbitalElements, RaanDifferenceEntersDiyAndDlambda) {
  const KeplerianElements chief = test::visors_chief();
  KeplerianElements deputy = chief;
  deputy.raan += 1e-5;
  const auto roe = roe_from_keplerian(chief, deputy).value();
  EXPECT_NEAR(roe[roe::kDlambda], 1e-5 * std::cos(chief.i), 1e-15);  // round-off of raan + 1e-5
  EXPECT_NEAR(roe[roe::kDiy], 1e-5 * std::sin(chief.i), 1e-15);
}

// Convention: dlambda is wrapped to (-pi, pi] even if M differ by whole revolutions.
TEST(RelativeOrbitalElements, DlambdaWrapped) {
  const KeplerianElements chief = test::visors_chief(10.0);
  KeplerianElements deputy = chief;
  deputy.M += 4.0 * visors::core::kPi + 0.1;
  // loose: measured 3.6e-16 rad (2026-11), bound 1e-13 ~280x above round-off
  EXPECT_NEAR(roe_from_keplerian(chief, deputy).value()[roe::kDlambda], 0.1, 1e-13);
}

TEST(RelativeOrbitalElementsInput, EquatorialChiefRejected) {
  KeplerianElements chief = test::visors_chief();
  chief.i = 0.0;
  EXPECT_EQ(roe_from_keplerian(chief, test::visors_chief()).error().field, "chief.i");
}
TEST(RelativeOrbitalElementsInput, BadDeputyEccentricityNamed) {
  KeplerianElements deputy = test::visors_chief();
  deputy.e = 1.5;
  EXPECT_EQ(roe_from_keplerian(test::visors_chief(), deputy).error().field, "deputy.e");
}
TEST(RelativeOrbitalElementsInput, DaBelowMinusOneRejected) {
  RelativeOrbitalElements roe = RelativeOrbitalElements::Zero();
  roe[roe::kDa] = -1.0;
  EXPECT_EQ(deputy_from_roe(test::visors_chief(), roe).error().field, "roe.da");
}

}  // namespace
