// GVE control input matrix against the exact change of the (osculating = two-body mean)
// elements after an impulse.
#include <gtest/gtest.h>

#include <cmath>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "astro_test_support.hpp"
#include "visors/core/rtn_frame.hpp"

namespace {
using namespace visors::astro;
using visors::astro::test::kDeg;
const double kMu = visors::core::EarthGravityConstants{}.mu;

// Impulse given in the chief's RTN axes, expressed in GCRF (core::gcrf_to_rtn_matrix transposed).
Eigen::Vector3d to_inertial(const visors::core::StateVector& chief, const Eigen::Vector3d& dv_rtn) {
  return visors::core::gcrf_to_rtn_matrix(chief).transpose() * dv_rtn;
}

// Exact ROE jump: the spacecraft (elements `sc`) receives dv_rtn (RTN of `chief`); ROE of the
// spacecraft w.r.t. the chief after minus before.
RelativeOrbitalElements exact_jump(const KeplerianElements& chief, const KeplerianElements& sc,
                                   const Eigen::Vector3d& dv_rtn, double mu) {
  const visors::core::StateVector x_c = cartesian_from_keplerian(chief, mu);
  const visors::core::StateVector x = cartesian_from_keplerian(sc, mu);
  const KeplerianElements after = cartesian_to_keplerian(x.r, x.v + to_inertial(x_c, dv_rtn), mu).value();
  return roe_from_keplerian(chief, after).value() - roe_from_keplerian(chief, sc).value();
}

// Property: Gamma is the exact first-order map: the error is second order in dv (halving dv
// divides it by ~4: ratio 3.5..4.5), eccentric chiefs, several anomalies, burn by the chief.
TEST(ControlInputMatrix, ErrorIsSecondOrderInDv) {
  const Eigen::Vector3d dir(0.3, -0.8, 0.5);
  for (double e : {0.004, 0.1, 0.5}) {
    for (double m_deg : {10.0, 100.0, 200.0, 300.0}) {
      const KeplerianElements chief{7.2e6, e, 60.0 * kDeg, 1.0, 2.0, m_deg * kDeg};
      const ControlInputMatrix gamma = control_input_matrix(chief, kMu);
      auto err = [&](double scale) {
        const Eigen::Vector3d dv = scale * dir;
        return (exact_jump(chief, chief, dv, kMu) - gamma * dv).cwiseAbs().maxCoeff();
      };
      EXPECT_NEAR(err(2e-3) / err(1e-3), 4.0, 0.5) << "e " << e << " M " << m_deg;
    }
  }
}

// Property: at dv = 1 mm/s the error is small relative to the jump (below 1e-6 relative).
TEST(ControlInputMatrix, SmallRelativeErrorAtOneMillimetrePerSecond) {
  double worst = 0.0;
  for (double e : {0.004, 0.1, 0.5}) {
    for (double m_deg = 0.0; m_deg < 360.0; m_deg += 45.0) {
      const KeplerianElements chief{7.2e6, e, 60.0 * kDeg, 1.0, 2.0, m_deg * kDeg};
      const Eigen::Vector3d dv(1e-3, -1e-3, 1e-3);
      const RelativeOrbitalElements gdv = control_input_matrix(chief, kMu) * dv;
      worst = std::max(worst, (exact_jump(chief, chief, dv, kMu) - gdv).cwiseAbs().maxCoeff() / gdv.cwiseAbs().maxCoeff());
    }
  }
  RecordProperty("max_relative_error", testing::PrintToString(worst));
  // measured regression bound: 5.8e-7 relative (2026-11); bound 1e-6
  EXPECT_LT(worst, 1e-6);
}

// Property (docs/algorithms/relative-motion.md#control-input-matrix): without Lambda_R, Lambda_T
// the dlambda row has a FIRST-order error (it does not shrink relative to the jump as dv -> 0),
// of size O(e).
TEST(ControlInputMatrix, LambdaTermsAreNeededForDlambda) {
  const KeplerianElements chief{7.2e6, 0.1, 60.0 * kDeg, 1.0, 2.0, 100.0 * kDeg};
  const Eigen::Vector3d dv(1e-4, 1e-4, 0.0);
  const double exact = exact_jump(chief, chief, dv, kMu)[roe::kDlambda];
  const double with = (control_input_matrix(chief, kMu) * dv)[roe::kDlambda];
  const double without = (control_input_matrix_without_lambda_terms(chief, kMu) * dv)[roe::kDlambda];
  // first-order map: error O(dv^2), measured 4.5e-16 vs bound 2.6e-14 (2026-11); the missing terms are O(e) of the jump: measured 5.8e-2 relative (e = 0.1) vs 1e-2
  EXPECT_LT(std::abs(with - exact), 1e-6 * std::abs(exact));
  EXPECT_GT(std::abs(without - exact), 1e-2 * std::abs(exact));
}

// Property: at e = 0 the eccentric Gamma equals the near-circular one.
TEST(ControlInputMatrix, ReducesToNearCircular) {
  const KeplerianElements chief{7.0e6, 0.0, 1.0, 0.5, 0.0, 2.0};
  // round-off (identical formulas at e = 0); measured 0 (2026-11)
  EXPECT_LT((control_input_matrix(chief, kMu) - control_input_matrix_near_circular(chief, kMu)).cwiseAbs().maxCoeff(),
            1e-18);
}

// Regression: the worked example in
// docs/algorithms/relative-motion.md#worked-example-impulse-on-the-science-orbit (evaluated
// independently): VISORS chief argp 90 deg, M = 60 deg, deputy on the science ROE receives
// dv_rtn = (1, 2, 3) mm/s along the chief's RTN axes; constants mu 3.986004418e14, R_E 6378137 m.
// a*Delta(roe) [m]: exact (3.62756, -1.79807, -2.69367, 2.57627, -2.35209, 1.33628); Gamma with
// Lambda terms gives dlambda -1.79806, without -1.80345; near-circular (3.61408, -1.80704,
// -2.67812, 2.58951, -2.34741, 1.35528).
class ControlInputWorkedExample : public ::testing::Test {
 protected:
  static constexpr double kMuExample = 3.986004418e14;
  KeplerianElements chief{6378137.0 + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, 60.0 * kDeg};
  Eigen::Vector3d dv{1e-3, 2e-3, 3e-3};
  RelativeOrbitalElements science() const {
    RelativeOrbitalElements r;
    r << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;
    return r / chief.a;
  }
};
TEST_F(ControlInputWorkedExample, ExactJump) {
  const KeplerianElements deputy = deputy_from_roe(chief, science()).value();
  const RelativeOrbitalElements jump = exact_jump(chief, deputy, dv, kMuExample) * chief.a;
  RelativeOrbitalElements ref;
  ref << 3.62756, -1.79807, -2.69367, 2.57627, -2.35209, 1.33628;
  // the worked example prints a*Delta(roe) to 1e-5 m; measured 5.0e-6 m (2026-11)
  EXPECT_LT((jump - ref).cwiseAbs().maxCoeff(), 1e-5);
}
TEST_F(ControlInputWorkedExample, GammaWithLambdaDlambda) {
  // the worked example prints 1e-5 m; measured 3.5e-8 m (2026-11)
  EXPECT_NEAR((control_input_matrix(chief, kMuExample) * dv)[roe::kDlambda] * chief.a, -1.79806, 1e-5);
}
TEST_F(ControlInputWorkedExample, GammaWithoutLambdaDlambda) {
  // the worked example prints 1e-5 m; measured 4.1e-6 m (2026-11)
  EXPECT_NEAR((control_input_matrix_without_lambda_terms(chief, kMuExample) * dv)[roe::kDlambda] * chief.a, -1.80345, 1e-5);
}
TEST_F(ControlInputWorkedExample, NearCircularGamma) {
  RelativeOrbitalElements ref;
  ref << 3.61408, -1.80704, -2.67812, 2.58951, -2.34741, 1.35528;
  // the worked example prints 1e-5 m; measured 3.5e-6 m (2026-11)
  EXPECT_LT(((control_input_matrix_near_circular(chief, kMuExample) * dv) * chief.a - ref).cwiseAbs().maxCoeff(), 1e-5);
}

}  // namespace
