// Closed-form impulsive planner: the standby -> science worked example (Keplerian;
// docs/algorithms/control.md#worked-example-standby-to-science), the dominant cases against the
// lower bounds with J2 and the eccentric Gamma, exactness in the linear model, a J2 numerical
// propagation of the mission transfer, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/control/closed_form_planner.hpp"
#include "control/j2_numerical_propagation.hpp"
#include "control/mission.hpp"
#include "visors/control/delta_v_lower_bound.hpp"
#include "visors/core/gps_time.hpp"

namespace visors::control {
namespace {

constexpr double kDeg = core::kDegToRad;
const core::EarthGravityConstants kJ2{};
const core::EarthGravityConstants kKepler{kJ2.mu, kJ2.re, 0.0};

using test::mission_chief;

double orbit_period(const astro::KeplerianElements& c, const core::EarthGravityConstants& g) {
  const astro::J2SecularRates r = astro::j2_secular_rates(c, g);
  return core::kTwoPi / (r.argp_dot + r.M_dot);
}

// Mission ROE (Guffanti et al., AAS 23-149, 2023, Table 5): standby a*[0,0,0,200,0,200],
// science a*[-2.62,45.21,-34.51,4.78,-18.72,2.72] m.
astro::RelativeOrbitalElements standby(double a) {
  return astro::RelativeOrbitalElements{0, 0, 0, 200, 0, 200} / a;
}
astro::RelativeOrbitalElements science(double a) {
  return astro::RelativeOrbitalElements{-2.62, 45.21, -34.51, 4.78, -18.72, 2.72} / a;
}

double terminal_error_m(const ManeuverPlan& plan, const astro::RelativeOrbitalElements& target, double a) {
  return a * (plan.roe_final_predicted - target).norm();
}

// Worked example docs/algorithms/control.md#worked-example-standby-to-science (Keplerian, e = 0,
// u0 = 0, 1.5 orbits; the three-tangential-burn closed form of Gaias & D'Amico 2015 / Chernick &
// D'Amico 2018, evaluated independently): in-plane burns dv_T = (-29.3163, +54.1291, -26.2627) mm/s at
// u = 79.98, 259.98, 439.98 deg (cost 0.10971 m/s, equal to the de bound), normal burn
// |dv_N| = 0.21933 m/s at u = 264.58 deg mod 180.
TEST(ClosedFormPlanner, ReproducesTheWorkedStandbyToScience) {
  astro::KeplerianElements chief = mission_chief();
  chief.e = 0.0;
  chief.argp = 0.0;
  const double a = chief.a;
  const double n = std::sqrt(kKepler.mu / (a * a * a));
  const double tf = 1.5 * core::kTwoPi / n;
  const auto plan = plan_closed_form(chief, standby(a), science(a), tf, {}, kKepler);
  ASSERT_TRUE(plan.ok()) << plan.error().describe();
  std::vector<double> tangential;
  double normal = 0.0;
  for (const Impulse& imp : plan->impulses) {
    if (std::abs(imp.dv_rtn.y()) > 1e-6) {
      tangential.push_back(imp.dv_rtn.y());
      // worked example's burn phases printed to 0.01 deg; measured 1.1e-4 deg (2026-11)
      EXPECT_NEAR(std::fmod(imp.t * n / kDeg, 180.0), 79.975, 0.01);
    }
    if (std::abs(imp.dv_rtn.z()) > 1e-6) {
      normal += std::abs(imp.dv_rtn.z());
      // worked example, 264.58 deg mod 180, printed to 0.01 deg; measured 4.1e-4 deg (2026-11)
      EXPECT_NEAR(std::fmod(imp.t * n / kDeg, 180.0), 84.579, 0.01);
    }
  }
  ASSERT_EQ(tangential.size(), 3u);
  // the worked example prints 1e-4 mm/s; measured 5.5e-10, 3.1e-8, 1.7e-8 m/s (2026-11)
  EXPECT_NEAR(tangential[0], -29.3163e-3, 1e-7);
  EXPECT_NEAR(tangential[1], 54.1291e-3, 1e-7);
  EXPECT_NEAR(tangential[2], -26.2627e-3, 1e-7);
  // the worked example prints 1e-5 m/s; measured 2.9e-6, 4.8e-6 m/s (2026-11); terminal: planner's terminal_tolerance_m 1e-6 m (closed_form_planner.hpp), measured 2.5e-14 m
  EXPECT_NEAR(normal, 0.21933, 1e-5);
  EXPECT_NEAR(plan->dv_total_mps, 0.10971 + 0.21933, 1e-5);
  EXPECT_LT(terminal_error_m(plan.value(), science(a), a), 1e-6);
}

struct DominantCase {
  const char* name;
  astro::RelativeOrbitalElements w_m;  // pseudostate [m]
  double orbits;
};

// Acceptance (b): in its dominant cases the plan (J2, eccentric Gamma, mission chief) costs
// within 1% of the lower bound of delta_v_lower_bound; the dlambda case is compared with the full
// dual bound (the tangential-only bound is reached to O(e)); integer-orbit window so that the
// two end burns have the same phase and their delta-e effects cancel.
TEST(ClosedFormPlanner, ReachesTheBoundInDominantCases) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double T = orbit_period(chief, kJ2);
  const std::vector<DominantCase> cases = {
      {"de", {0, 0, -34.51, -195.22, 0, 0}, 1.5},
      {"de_with_da_dlambda", {-2.62, 45.21, -34.51, -195.22, 0, 0}, 1.5},
      {"da", {20, -1.5 * 2.0 * core::kTwoPi * 20, 3, 4, 0, 0}, 3.0},
      {"dlambda", {0, 300, 0, 0, 0, 0}, 2.0},
      {"out_of_plane", {0, 0, 0, 0, -18.72, -197.28}, 1.5},
  };
  for (const DominantCase& c : cases) {
    const double tf = c.orbits * T;
    const astro::RelativeOrbitalElements target = c.w_m / a;  // roe0 = 0: the pseudostate is the target
    const auto plan = plan_closed_form(chief, astro::RelativeOrbitalElements::Zero(), target, tf, {}, kJ2);
    ASSERT_TRUE(plan.ok()) << c.name << ": " << plan.error().describe();
    const auto bound = delta_v_lower_bound(chief, target, tf, kJ2).value();
    const double ratio = plan->dv_total_mps / bound.total;
    RecordProperty(std::string("cost_over_bound_") + c.name, testing::PrintToString(ratio));
    std::cout << c.name << ": cost " << plan->dv_total_mps << " m/s, bound " << bound.total << " m/s, ratio " << ratio << "\n";
    EXPECT_GE(ratio, 1.0 - chief.e) << c.name;  // first-order-in-e bound (see its header)
    EXPECT_LE(ratio, 1.01) << c.name << " cost " << plan->dv_total_mps << " bound " << bound.total;
    // same bound computation: measured 0; terminal_tolerance_m 1e-6 m (closed_form_planner.hpp): measured 1.4e-13 m (2026-11); ratio measured 0.9967 .. 1.003
    EXPECT_NEAR(plan->dv_lower_bound_mps, bound.total, 1e-15) << c.name;
    EXPECT_LT(terminal_error_m(plan.value(), target, a), 1e-6) << c.name;
  }
}

// Outside the dominant cases the bound is not attainable: a dlambda-dominant target with a
// delta-e that the end burns cannot produce (3 orbits) costs more than the dual bound; measured
// 2.9% above it. The plan stays exact and within 5% of the bound.
TEST(ClosedFormPlanner, DlambdaWithDeltaEIsNearTheBound) {
  const astro::KeplerianElements chief = mission_chief();
  const double tf = 3.0 * orbit_period(chief, kJ2);
  const astro::RelativeOrbitalElements target = astro::RelativeOrbitalElements{1, -500, 2, 1, 0, 0} / chief.a;
  const auto plan = plan_closed_form(chief, astro::RelativeOrbitalElements::Zero(), target, tf, {}, kJ2);
  ASSERT_TRUE(plan.ok());
  const double ratio = plan->dv_total_mps / plan->dv_lower_bound_mps;
  RecordProperty("cost_over_bound", testing::PrintToString(ratio));
  EXPECT_GE(ratio, 1.0);
  EXPECT_LE(ratio, 1.05);
  // planner's terminal_tolerance_m 1e-6 m (closed_form_planner.hpp); measured 9.3e-14 m (2026-11)
  EXPECT_LT(terminal_error_m(plan.value(), target, chief.a), 1e-6);
}

// Acceptance (c), linear model: the mission transfer standby -> science over 1.5-3 orbits, with
// one and with two normal burns, reaches the target to 1e-6 m in a*ROE, and roe_final_predicted
// is the linear propagation of roe0 with the impulses. The cost is within 1% of the sum of the
// in-plane and out-of-plane bounds (separate burns; the coupled bound hypot(in, out) is lower).
TEST(ClosedFormPlanner, MissionTransferIsExactInTheLinearModel) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double T = orbit_period(chief, kJ2);
  for (double orbits : {1.5, 2.0, 3.0}) {
    for (int normal_burns : {1, 2}) {
      ClosedFormSettings s;
      s.normal_burns = normal_burns;
      const auto plan = plan_closed_form(chief, standby(a), science(a), orbits * T, s, kJ2);
      ASSERT_TRUE(plan.ok()) << plan.error().describe();
      EXPECT_LT(terminal_error_m(plan.value(), science(a), a), 1e-6) << orbits;
      const astro::RelativeOrbitalElements again = predict_roe(chief, standby(a), plan->impulses, orbits * T, kJ2);
      // same linear propagation, round-off; measured 0 (2026-11)
      EXPECT_LT(a * (again - plan->roe_final_predicted).norm(), 1e-9);
      const astro::RelativeOrbitalElements w = science(a) - astro::j2_roe_stm(chief, orbits * T, kJ2) * standby(a);
      const auto b = delta_v_lower_bound(chief, w, orbits * T, kJ2).value();
      EXPECT_LE(plan->dv_total_mps, 1.01 * (b.in_plane + b.out_of_plane)) << orbits;
      // lower bound by definition (delta_v_lower_bound.hpp); measured 0.328 >= 0.245 m/s (2026-11); the 1% above: measured 0.328 vs 0.332 m/s
      EXPECT_GE(plan->dv_total_mps, plan->dv_lower_bound_mps);
      int normals = 0;
      for (const Impulse& imp : plan->impulses) normals += std::abs(imp.dv_rtn.z()) > 0.05 ? 1 : 0;
      EXPECT_EQ(normals, normal_burns);
    }
  }
}

// Acceptance (c), J2 numerical propagation (J2-only force model, Dormand-Prince 8(7)): the
// terminal mean-ROE error of the mission transfer, a*||droe||, is at the metre level expected of
// the first-order model (linearisation of a ~0.33 m/s transfer, mean/osculating map truncation).
TEST(ClosedFormPlanner, MissionTransferInJ2NumericalPropagation) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double T = orbit_period(chief, kJ2);
  for (double orbits : {1.5, 3.0}) {
    const auto plan = plan_closed_form(chief, standby(a), science(a), orbits * T, {}, kJ2);
    ASSERT_TRUE(plan.ok());
    const astro::RelativeOrbitalElements final_roe =
        test::propagate_j2_numerically(chief, standby(a), plan->impulses, orbits * T);
    const Eigen::Vector<double, 6> err_m = a * (final_roe - science(a));
    RecordProperty("terminal_error_m_" + std::to_string(orbits), testing::PrintToString(err_m.transpose()));
    std::cout << "orbits " << orbits << " terminal a*dROE error [m]: " << err_m.transpose() << " norm "
              << err_m.norm() << "\n";
    // measured regression bound: 0.27 m (2026-11); bound 5 m (metre level, comment above)
    EXPECT_LT(err_m.norm(), 5.0) << err_m.transpose();
  }
}

// Acceptance (e): every rejection names its field.
TEST(ClosedFormPlanner, RejectsBadInput) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double T = orbit_period(chief, kJ2);
  auto field = [&](const astro::KeplerianElements& c, const astro::RelativeOrbitalElements& r0,
                   const astro::RelativeOrbitalElements& rt, double tf, const ClosedFormSettings& s = {}) {
    const auto p = plan_closed_form(c, r0, rt, tf, s, kJ2);
    EXPECT_FALSE(p.ok());
    return p.ok() ? std::string() : p.error().field;
  };
  EXPECT_EQ(field(chief, standby(a), science(a), 1.4 * T), "tf");  // horizon too short
  EXPECT_EQ(field(chief, standby(a), science(a), NAN), "tf");
  astro::RelativeOrbitalElements nan_roe = standby(a);
  nan_roe[2] = NAN;
  EXPECT_EQ(field(chief, nan_roe, science(a), 2 * T), "roe0");
  EXPECT_EQ(field(chief, standby(a), nan_roe, 2 * T), "roe_target");
  astro::KeplerianElements bad = chief;
  bad.e = 0.3;
  EXPECT_EQ(field(bad, standby(a), science(a), 2 * T), "chief_mean_t0.e");
  bad = chief;
  bad.M = INFINITY;
  EXPECT_EQ(field(bad, standby(a), science(a), 2 * T), "chief_mean_t0.M");
  bad = chief;
  bad.i = 0.0;
  EXPECT_EQ(field(bad, standby(a), science(a), 2 * T), "chief_mean_t0.i");
  ClosedFormSettings s;
  s.earliest_burn_s = 0.6 * T;  // leaves 1.4 orbits in a 2-orbit horizon
  EXPECT_EQ(field(chief, standby(a), science(a), 2 * T, s), "tf");
  s = {};
  s.normal_burns = 3;
  EXPECT_EQ(field(chief, standby(a), science(a), 2 * T, s), "settings.normal_burns");
  s = {};
  s.end_margin_s = -1.0;
  EXPECT_EQ(field(chief, standby(a), science(a), 2 * T, s), "settings.end_margin_s");
  // The singular-geometry path: a terminal tolerance below round-off cannot be met.
  s = {};
  s.terminal_tolerance_m = 1e-300;
  EXPECT_EQ(field(chief, standby(a), science(a), 2 * T, s), "roe_target");
}

// Settings: burns respect the window [earliest_burn, tf - end_margin]; a target equal to the free
// drift needs no impulse.
TEST(ClosedFormPlanner, RespectsTheBurnWindowAndFreeDrift) {
  const astro::KeplerianElements chief = mission_chief();
  const double a = chief.a;
  const double T = orbit_period(chief, kJ2);
  ClosedFormSettings s;
  s.earliest_burn_s = 600.0;
  s.end_margin_s = 900.0;
  const auto plan = plan_closed_form(chief, standby(a), science(a), 2.0 * T, s, kJ2);
  ASSERT_TRUE(plan.ok());
  for (const Impulse& imp : plan->impulses) {
    // the settings' burn window [600 s, 2T - 900 s]; measured 2.7e3 .. 9.05e3 s within [600, 1.05e4] s (2026-11)
    EXPECT_GE(imp.t, 600.0);
    EXPECT_LE(imp.t, 2.0 * T - 900.0);
  }
  // planner's terminal_tolerance_m 1e-6 m (closed_form_planner.hpp); measured 6.5e-14 m (2026-11)
  EXPECT_LT(terminal_error_m(plan.value(), science(a), a), 1e-6);
  const astro::RelativeOrbitalElements drift = astro::j2_roe_stm(chief, 2.0 * T, kJ2) * science(a);
  const auto none = plan_closed_form(chief, science(a), drift, 2.0 * T, {}, kJ2);
  ASSERT_TRUE(none.ok());
  EXPECT_TRUE(none->impulses.empty());
  EXPECT_EQ(none->dv_total_mps, 0.0);
}

}  // namespace
}  // namespace visors::control
