// ROE state transition matrices against an independent numerical Jacobian of the model they
// linearise, plus regression tables (worked example in
// docs/algorithms/relative-motion.md#worked-example-j2-stm-for-the-visors-chief).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/astro/roe_stm.hpp"
#include "astro_test_support.hpp"
#include "visors/core/angles.hpp"

namespace {
using namespace visors::astro;
using visors::astro::test::kDeg;
const visors::core::EarthGravityConstants kGravity;

// Nonlinear model: deputy from (chief, roe0), both propagated with the secular J2 rates of their
// own mean elements, exact ROE differencing at t0 + tau.
RelativeOrbitalElements propagate_roe_secular(const KeplerianElements& chief,
                                              const RelativeOrbitalElements& roe0, double tau,
                                              const visors::core::EarthGravityConstants& g) {
  const KeplerianElements deputy = deputy_from_roe(chief, roe0).value();
  auto wrap = [](KeplerianElements el) {
    el.raan = visors::core::wrap_two_pi(el.raan);
    el.argp = visors::core::wrap_two_pi(el.argp);
    el.M = visors::core::wrap_two_pi(el.M);
    return el;
  };
  return roe_from_keplerian(wrap(propagate_mean_j2(chief, tau, g)), wrap(propagate_mean_j2(deputy, tau, g)))
      .value();
}

// Central finite differences at roe0 = 0, step 1e-5: measured 1e-9 (steps 1e-6 and 1e-4 give 8e-9
// and 1.5e-8: round-off of differencing ~60 rad angles, resp. truncation O(h^2)).
RoeStm numerical_jacobian(const KeplerianElements& chief, double tau) {
  RoeStm jac;
  const double h = 1e-5;
  for (int k = 0; k < 6; ++k) {
    RelativeOrbitalElements step = RelativeOrbitalElements::Zero();
    step[k] = h;
    jac.col(k) = (propagate_roe_secular(chief, step, tau, kGravity) -
                  propagate_roe_secular(chief, -step, tau, kGravity)) /
                 (2.0 * h);
  }
  return jac;
}

// Relative difference, element-wise against the max norm of each column of the reference.
double column_relative_difference(const RoeStm& phi, const RoeStm& ref) {
  double worst = 0.0;
  for (int k = 0; k < 6; ++k) {
    worst = std::max(worst, (phi.col(k) - ref.col(k)).cwiseAbs().maxCoeff() / ref.col(k).cwiseAbs().maxCoeff());
  }
  return worst;
}

// Property: KGD17 eq. (A6) is the Jacobian of secular-J2 mean propagation (1e-8 relative), for
// the VISORS chief, an eccentric chief and a near-circular low-inclination chief, tau 0.1..10
// orbits.
TEST(J2RoeStm, MatchesNumericalJacobianOfSecularPropagation) {
  const double re = kGravity.re;
  double worst = 0.0;
  for (const KeplerianElements& chief :
       {test::visors_chief(0.0), KeplerianElements{re + 1500e3, 0.1, 45.0 * kDeg, 20.0 * kDeg, 40.0 * kDeg, 1.0},
        KeplerianElements{re + 700e3, 1e-4, 28.0 * kDeg, 200.0 * kDeg, 300.0 * kDeg, 3.0}}) {
    const double period = 2.0 * visors::core::kPi * std::sqrt(chief.a * chief.a * chief.a / kGravity.mu);
    for (double orbits : {0.1, 1.0, 3.3, 10.0}) {
      const double tau = orbits * period;
      worst = std::max(worst, column_relative_difference(j2_roe_stm(chief, tau, kGravity),
                                                         numerical_jacobian(chief, tau)));
    }
  }
  RecordProperty("max_relative_difference", testing::PrintToString(worst));
  EXPECT_LT(worst, 1e-8);
}

// Property: the Keplerian STM is exact within its model (two-body: only dlambda drifts).
TEST(KeplerianRoeStm, ExactForTwoBodyPropagation) {
  const KeplerianElements chief{7.2e6, 0.3, 1.0, 2.0, 0.5, 0.2};
  RelativeOrbitalElements roe0;
  roe0 << 1e-5, 2e-5, -3e-5, 4e-5, 1e-5, -2e-5;
  const double tau = 20000.0;
  const KeplerianElements deputy = deputy_from_roe(chief, roe0).value();
  const auto roe_f =
      roe_from_keplerian(propagate_kepler(chief, tau, kGravity.mu), propagate_kepler(deputy, tau, kGravity.mu))
          .value();
  // the nonlinear dlambda drift is -n_c tau ((1 + da)^-1.5 - 1); the STM keeps its linear part
  const double n = std::sqrt(kGravity.mu / std::pow(chief.a, 3));
  RelativeOrbitalElements expected = keplerian_roe_stm(chief, tau, kGravity.mu) * roe0;
  expected[roe::kDlambda] += n * tau * (std::pow(1.0 + roe0[0], -1.5) - 1.0 + 1.5 * roe0[0]);
  EXPECT_LT((roe_f - expected).cwiseAbs().maxCoeff(), 2e-14);  // angle round-off over n tau = 20 rad
}

// Regression (NOT an independent check: the same formulas, evaluated independently): the worked
// example in docs/algorithms/relative-motion.md#worked-example-j2-stm-for-the-visors-chief, VISORS
// chief argp 90 deg, M = 0, with the constants it was evaluated with (mu 3.986004418e14,
// R_E 6378137 m, a = R_E + 500 km). Columns: secular-J2 propagation of chief and deputy mean
// elements with exact ROE differencing, and eq. (A6) times roe0. a*roe in metres.
const visors::core::EarthGravityConstants kExampleGravity{3.986004418e14, 6378137.0, 1.08262668e-3};
struct Row {
  std::vector<double> roe0;
  double tau;
  std::vector<double> nonlinear;
  std::vector<double> stm;
};
TEST(J2RoeStm, WorkedExampleLongHorizonRegression) {
  const KeplerianElements chief{kExampleGravity.re + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, 0.0};
  const std::vector<double> sci{-2.62, 45.21, -34.51, 4.78, -18.72, 2.72};
  const double orbit = 2.0 * visors::core::kPi * std::sqrt(std::pow(chief.a, 3) / kExampleGravity.mu);
  const std::vector<Row> rows{
      {sci, orbit, {-2.62, 69.6718, -34.4901, 4.9174, -18.72, 2.5697}, {-2.62, 69.6718, -34.4901, 4.9174, -18.72, 2.5697}},
      {sci, 86400.0, {-2.62, 417.5025, -34.1481, 6.8614, -18.72, 0.4322}, {-2.62, 417.5023, -34.1481, 6.8614, -18.72, 0.4322}},
      {sci, 864000.0, {-2.62, 3768.1348, -25.5638, 23.5394, -18.72, -20.1577}, {-2.62, 3768.1332, -25.5638, 23.5394, -18.72, -20.1577}},
      {{5, 0, 0, 200, 0, 200}, 86400.0, {5, -715.3418, 12.1131, 199.6328, 0, 199.7434}, {5, -715.3411, 12.1132, 199.6328, 0, 199.7432}}};
  double worst_nl = 0.0;
  double worst_stm = 0.0;
  for (const Row& row : rows) {
    const RelativeOrbitalElements roe0 = Eigen::Map<const RelativeOrbitalElements>(row.roe0.data()) / chief.a;
    const RelativeOrbitalElements nl = propagate_roe_secular(chief, roe0, row.tau, kExampleGravity) * chief.a;
    const RelativeOrbitalElements lin = j2_roe_stm(chief, row.tau, kExampleGravity) * roe0 * chief.a;
    for (int k = 0; k < 6; ++k) {
      worst_nl = std::max(worst_nl, std::abs(nl[k] - row.nonlinear[static_cast<std::size_t>(k)]));
      worst_stm = std::max(worst_stm, std::abs(lin[k] - row.stm[static_cast<std::size_t>(k)]));
    }
  }
  EXPECT_LT(worst_nl, 1.5e-4);   // printed to 1e-4 m
  EXPECT_LT(worst_stm, 1.5e-4);
}

// Regression: the one-orbit matrix entries of the same worked example (1-based indices there).
TEST(J2RoeStm, WorkedExampleOneOrbitRegression) {
  const KeplerianElements chief{kExampleGravity.re + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, 0.0};
  const double orbit = 2.0 * visors::core::kPi * std::sqrt(std::pow(chief.a, 3) / kExampleGravity.mu);
  const RoeStm phi = j2_roe_stm(chief, orbit, kExampleGravity);
  // tolerances = last printed digit of the worked example's entries; measured 1.3e-7, 1.8e-9, 2.5e-9, 3.5e-9, 5.0e-9, 4.6e-9 (2026-11)
  EXPECT_NEAR(phi(1, 0), -9.395765, 1e-6);
  EXPECT_NEAR(phi(1, 4), 8.25846e-3, 1e-8);
  EXPECT_NEAR(phi(2, 2), 0.99999207, 1e-8);
  EXPECT_NEAR(phi(3, 2), -3.98309e-3, 1e-8);
  EXPECT_NEAR(phi(5, 0), -4.12925e-3, 1e-8);
  EXPECT_NEAR(phi(5, 4), 8.61264e-3, 1e-8);
}

}  // namespace
