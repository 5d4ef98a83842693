// Single-impulse escape (docs/algorithms/safety.md#escape-maneuver): the prescribed drift, the e/i
// conditions and the q-sigma safety after the burn in the linear model, the impulse checked by
// exact element differencing and by a numerical J2 propagation, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/j2_secular.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "visors/safety/escape_maneuver.hpp"

namespace visors::safety {
namespace {

using astro::RelativeOrbitalElements;
namespace idx = astro::roe;
constexpr double kDeg = core::kDegToRad;

astro::KeplerianElements mission_chief(double mean_anomaly = 0.0) {
  return {6378136.3 + 500e3, 0.004, 97.8 * kDeg, 157.5 * kDeg, 90.0 * kDeg, mean_anomaly};
}

// Mission science orbit, a*roe = [-2.62, 45.21, -34.51, 4.78, -18.72, 2.72] m.
RelativeOrbitalElements science_roe(double a) {
  RelativeOrbitalElements roe;
  roe << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;
  return roe / a;
}

RoeCovariance test_covariance(double a) {
  Eigen::Matrix<double, 6, 6> l = Eigen::Matrix<double, 6, 6>::Zero();
  const double sig[6] = {0.3, 2.0, 0.5, 0.5, 0.4, 0.4};
  for (int k = 0; k < 6; ++k) l(k, k) = sig[k];
  l(3, 2) = 0.2;
  l(5, 4) = -0.15;
  return (l * l.transpose()) / (a * a);
}

double cross2(const RelativeOrbitalElements& roe) {
  return roe[idx::kDex] * roe[idx::kDiy] - roe[idx::kDey] * roe[idx::kDix];
}

// Issue text: 5 m of a*da drifts 47 m per orbit. Keplerian (J2 = 0): d(a dlambda) = -1.5 n T a da
// = -3 pi a da = +47.124 m for a da = -5 m (a deputy ahead escapes further ahead). With J2 the
// STM's (1.5 n + 3.5 kappa E P) rate and the di coupling give ~47 m (reported).
TEST(EscapeManeuver, FiveMetresOfDaDriftFortySevenMetresPerOrbit) {
  const auto chief = mission_chief();
  core::EarthGravityConstants kepler;
  kepler.j2 = 0.0;
  const auto escape = plan_escape(chief, science_roe(chief.a), RoeCovariance::Zero(), 0.0, EscapeSettings{}, kepler);
  ASSERT_TRUE(escape.ok()) << escape.error().describe();
  // exact by construction (target a*da = -5 m) and analytic 3 pi a da (comment above); measured 0 and 7.1e-15 m (2026-11); drift bound loose (~1e8x)
  EXPECT_NEAR(chief.a * escape->roe_after[idx::kDa], -5.0, 1e-9);
  EXPECT_NEAR(escape->drift_per_orbit_m, 3.0 * core::kPi * 5.0, 1e-6);
  const auto j2 = plan_escape(chief, science_roe(chief.a), RoeCovariance::Zero(), 0.0, EscapeSettings{});
  ASSERT_TRUE(j2.ok());
  // target a*da exact by construction; measured 0 (2026-11)
  EXPECT_NEAR(chief.a * j2->roe_after[idx::kDa], -5.0, 1e-9);
  // issue text: ~47 m per orbit with J2; measured regression bound: 0.18 m (2026-11); bound 0.3 m
  EXPECT_NEAR(j2->drift_per_orbit_m, 47.0, 0.3);
  RecordProperty("j2_drift_per_orbit_m", std::to_string(j2->drift_per_orbit_m));
}

// A deputy behind the chief (dlambda < 0) escapes with da > 0, drifting further behind.
TEST(EscapeManeuver, DriftIsAwayFromTheChief) {
  const auto chief = mission_chief();
  RelativeOrbitalElements roe = science_roe(chief.a);
  roe[idx::kDlambda] = -roe[idx::kDlambda];
  const auto escape = plan_escape(chief, roe, RoeCovariance::Zero(), 0.0, EscapeSettings{});
  ASSERT_TRUE(escape.ok());
  // target a*da exact by construction; issue text ~47 m per orbit: measured a*da error 0, drift -47.1 m (2026-11); bound -46 m
  EXPECT_NEAR(chief.a * escape->roe_after[idx::kDa], 5.0, 1e-9);
  EXPECT_LT(escape->drift_per_orbit_m, -46.0);
}

// Conditions (ii)-(iii) with uncertainty: after the burn the e/i vectors are parallel, the RN
// separation exceeds epsilon + q sigma over the horizon (independent re-evaluation with the
// post-burn covariance), |a da| = 5 m + 3 sigma(a da), and the burn is at t_earliest ("as soon as
// allowed").
TEST(EscapeManeuver, SeparationAfterEscapeExceedsEpsilonPlusQSigma) {
  const auto chief = mission_chief();
  const RoeCovariance p = test_covariance(chief.a);
  EscapeSettings s;
  s.epsilon_m = 10.0;
  const double t_earliest = 300.0;
  const auto escape = plan_escape(chief, science_roe(chief.a), p, t_earliest, s);
  ASSERT_TRUE(escape.ok()) << escape.error().describe();
  EXPECT_EQ(escape->impulse.t, t_earliest);
  const RelativeOrbitalElements& after = escape->roe_after;
  // e/i parallel (condition ii) and a*da = 5 m + 3 sigma, exact by construction; loose: measured 4.8e-15 m^2 (2026-11), bound 1e-9 ~2e5x above; a*da measured 0
  EXPECT_LT(std::abs(cross2(after)) * chief.a * chief.a, 1e-9);
  EXPECT_NEAR(chief.a * after[idx::kDa], -(5.0 + 3.0 * 0.3), 1e-9);
  PassiveSafetySettings check;
  check.epsilon_m = s.epsilon_m;
  const auto chief_b = astro::propagate_mean_j2(chief, t_earliest);
  const auto r = evaluate_passive_safety(chief_b, after, escape->covariance_after, check);
  ASSERT_TRUE(r.ok());
  // requirement: margin >= epsilon, q = 3 (docs/algorithms/safety.md#escape-maneuver, docs/conventions.md Safety); measured margin 16.2 m >= 10 m, min 17.6 m >= 11.3 m (2026-11)
  EXPECT_GE(r->min_separation_margin_m, s.epsilon_m);
  EXPECT_GE(r->min_separation_m, s.epsilon_m + 3.0 * r->sigma_at_t_min_m);
  RecordProperty("after_rn_min_m", std::to_string(r->min_separation_m));
  RecordProperty("after_margin_m", std::to_string(r->min_separation_margin_m));
}

// Worked example docs/algorithms/safety.md#worked-example-escape-from-the-science-orbit
// (near-circular closed forms evaluated independently): escape from the science orbit burned at
// u = phi_e + pi = 352.11 deg, target a da = -5 m: dv_T = (n/2)(a da_target - a da) = -1.317 mm/s,
// |a de| grows 34.84 -> 37.22 m along its own phase. The e/i vectors are 0.38 deg apart, so exact
// parallelism costs a radial component rotating de by 0.38 deg (n a |de| 0.0066 = 0.25 mm/s); no
// normal component.
TEST(EscapeManeuver, WorkedExampleFromTheScienceOrbit) {
  const auto chief = mission_chief((352.11 - 90.0) * kDeg);
  const auto escape = plan_escape(chief, science_roe(chief.a), RoeCovariance::Zero(), 0.0, EscapeSettings{});
  ASSERT_TRUE(escape.ok());
  const Eigen::Vector3d dv = escape->impulse.dv_rtn;
  // worked example: dv_T -1.317 mm/s, measured regression bound: 1.9e-3 mm/s (2026-11); bound 1e-2 mm/s. dv_R: analytic estimate 0.25 mm/s (comment above), measured 0.258 mm/s, bound 0.3 mm/s (1.16x)
  EXPECT_NEAR(dv.y(), -1.317e-3, 0.01e-3);
  EXPECT_LT(std::abs(dv.x()), 0.3e-3);
  // no normal component (comment above); loose: measured 2.7e-15 m/s (2026-11), bound 1e-5 m/s ~4e9x above
  EXPECT_LT(std::abs(dv.z()), 0.01e-3);
  // worked example: 37.22 m; measured regression bound: 1.6e-3 m (2026-11); bound 0.05 m
  EXPECT_NEAR(chief.a * std::hypot(escape->roe_after[idx::kDex], escape->roe_after[idx::kDey]), 37.22, 0.05);
  RecordProperty("test6b_dv_mm_s", std::to_string(dv.x() * 1e3) + " " + std::to_string(dv.y() * 1e3) + " " +
                                       std::to_string(dv.z() * 1e3));
  RecordProperty("test6b_rn_min_m", std::to_string(escape->safety_after.min_separation_m));
}

// The impulse in the exact two-body model: deputy elements from the mean ROE, Cartesian state,
// dv added in the deputy's RTN frame, elements differenced again. Agrees with Gamma dv to O(e dv
// and |roe| dv) terms: 1 mm in a*da, 2 cm in a*dlambda (the near-circular Gamma is ~1e-2 relative
// off, the eccentric Gamma ~1e-5: docs/algorithms/relative-motion.md#worked-example-impulse-on-the-science-orbit).
TEST(EscapeManeuver, ImpulseVerifiedByExactElementDifferencing) {
  const auto chief = mission_chief(40.0 * kDeg);
  const core::EarthGravityConstants g;
  const auto escape = plan_escape(chief, science_roe(chief.a), RoeCovariance::Zero(), 0.0, EscapeSettings{});
  ASSERT_TRUE(escape.ok());
  ASSERT_EQ(escape->impulse.t, 0.0);
  const auto deputy = astro::deputy_from_roe(chief, escape->roe_before).value();
  const core::StateVector x_dep = astro::cartesian_from_keplerian(deputy, g.mu);
  const Eigen::Vector3d r_hat = x_dep.r.normalized();
  const Eigen::Vector3d n_hat = x_dep.r.cross(x_dep.v).normalized();
  const Eigen::Vector3d t_hat = n_hat.cross(r_hat);
  const Eigen::Vector3d dv = escape->impulse.dv_rtn;
  const core::StateVector x_after{x_dep.r, x_dep.v + dv.x() * r_hat + dv.y() * t_hat + dv.z() * n_hat};
  const auto deputy_after = astro::cartesian_to_keplerian(x_after.r, x_after.v, g.mu).value();
  const RelativeOrbitalElements exact = astro::roe_from_keplerian(chief, deputy_after).value();
  const Eigen::Matrix<double, 6, 1> error_m = chief.a * (exact - escape->roe_after);
  // O(e dv) estimate in the comment above; measured 1.1e-5 m (da), 3.3e-6 m (e/i, loose ~600x below 2e-3), 1.0e-5 m (dlambda) (2026-11)
  EXPECT_LT(std::abs(error_m[idx::kDa]), 1e-3) << error_m.transpose();
  EXPECT_LT(error_m.tail<4>().cwiseAbs().maxCoeff(), 2e-3) << error_m.transpose();
  EXPECT_LT(std::abs(error_m[idx::kDlambda]), 2e-2) << error_m.transpose();
}

// Numerical check with the dynamics layer (J2-only field, Dormand-Prince 8(7)): chief and deputy
// mean elements -> osculating (first-order J2 map with the field's own J2) -> Cartesian; the
// deputy burns the escape dv in its RTN frame at t = 60 s; both propagated 3 orbits. Mean ROE are
// recovered (osculating -> mean) once per orbit: the drift of a*dlambda per orbit and a*da are
// compared with the linear J2 model, and the numerical RN separation (osculating, sampled every
// 10 s) stays above epsilon. Elements are taken in an inertial frame whose z axis is the Earth's
// pole (as in tests/dynamics/test_orbit_propagator.cpp: the J2 theory assumes it).
TEST(EscapeManeuver, DriftConfirmedByNumericalJ2Propagation) {
  using core::GpsTime;
  const GpsTime epoch = GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();
  dynamics::ForceModelConfig c = dynamics::ForceModelConfig::gravity_only(2, 0);
  auto forces_or = dynamics::files::load_force_model(c, dynamics::SpacecraftProperties{});
  ASSERT_TRUE(forces_or.ok()) << forces_or.error().describe();
  dynamics::ForceModel forces = std::move(forces_or).value();
  const auto file = dynamics::files::load_gravity_field(forces.config().gravity.model, 2);
  const dynamics::GravityField field = file.ok() ? file.value() : dynamics::embedded_gravity_field();
  const core::EarthGravityConstants earth{field.gm, field.radius, -std::sqrt(5.0) * field.c(2, 0)};
  dynamics::PropagatorSettings ps;
  ps.integrator = dynamics::IntegratorKind::kDormandPrince87;

  const auto chief = mission_chief();
  const RelativeOrbitalElements roe0 = science_roe(chief.a);
  const double t_burn = 60.0;
  const auto escape = plan_escape(chief, roe0, RoeCovariance::Zero(), t_burn, EscapeSettings{}, earth);
  ASSERT_TRUE(escape.ok()) << escape.error().describe();
  ASSERT_EQ(escape->impulse.t, t_burn);

  const Eigen::Vector3d pole = core::gcrf_to_itrf_matrix(epoch, {}).row(2).transpose();
  const Eigen::Vector3d x_axis = (Eigen::Vector3d::UnitX() - pole.x() * pole).normalized();
  Eigen::Matrix3d to_pole;  // GCRF -> pole frame
  to_pole << x_axis.transpose(), pole.cross(x_axis).transpose(), pole.transpose();
  const auto to_gcrf = [&](const astro::KeplerianElements& mean) {
    const core::StateVector x = astro::cartesian_from_keplerian(astro::osculating_from_mean(mean, earth).value(), earth.mu);
    return core::StateVector{to_pole.transpose() * x.r, to_pole.transpose() * x.v};
  };
  const auto mean_of = [&](const core::StateVector& x) {
    const auto osc = astro::cartesian_to_keplerian(to_pole * x.r, to_pole * x.v, earth.mu).value();
    return astro::mean_from_osculating(osc, earth).value();
  };
  const core::StateVector chief_x0 = to_gcrf(chief);
  const core::StateVector deputy_x0 = to_gcrf(astro::deputy_from_roe(chief, roe0).value());

  const double period = orbital_period(chief, earth.mu);
  const double t_end = t_burn + 3.0 * period;
  std::vector<GpsTime> outputs;
  for (double t = 0.0; t < t_end; t += 10.0) outputs.push_back(epoch + t);
  for (int k = 0; k <= 3; ++k) outputs.push_back(epoch + (t_burn + k * period));
  std::sort(outputs.begin(), outputs.end());
  outputs.erase(std::unique(outputs.begin(), outputs.end()), outputs.end());
  std::vector<core::StateVector> chief_states, deputy_states;
  auto p1 = dynamics::OrbitPropagator::create(forces, ps).value();
  ASSERT_TRUE(p1.propagate(epoch, chief_x0, outputs, {}, [&](GpsTime, const core::StateVector& x) {
                  chief_states.push_back(x);
                }).ok());
  const dynamics::ImpulsiveManeuver burn{epoch + t_burn, escape->impulse.dv_rtn, dynamics::ManeuverFrame::kRtn};
  auto p2 = dynamics::OrbitPropagator::create(forces, ps).value();
  ASSERT_TRUE(p2.propagate(epoch, deputy_x0, outputs, std::span<const dynamics::ImpulsiveManeuver>(&burn, 1),
                           [&](GpsTime, const core::StateVector& x) { deputy_states.push_back(x); })
                  .ok());
  ASSERT_EQ(chief_states.size(), outputs.size());
  ASSERT_EQ(deputy_states.size(), outputs.size());

  double rn_min = 1e300;
  std::vector<RelativeOrbitalElements> per_orbit;
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    const double t = outputs[k].seconds_since(epoch);
    if (t >= t_burn) {
      const core::RelativeStateRtn rel = core::relative_state_rtn(chief_states[k], deputy_states[k]);
      rn_min = std::min(rn_min, std::hypot(rel.dr_rtn.x(), rel.dr_rtn.z()));
    }
    for (int j = 0; j <= 3; ++j) {
      if (std::abs(t - (t_burn + j * period)) < 1e-6) {
        per_orbit.push_back(astro::roe_from_keplerian(mean_of(chief_states[k]), mean_of(deputy_states[k])).value());
      }
    }
  }
  ASSERT_EQ(per_orbit.size(), 4u);
  const auto chief_b = astro::propagate_mean_j2(chief, t_burn, earth);
  double worst = 0.0;
  for (int j = 1; j <= 3; ++j) {
    const RelativeOrbitalElements predicted = astro::j2_roe_stm(chief_b, j * period, earth) * escape->roe_after;
    const double drift_numeric = chief.a * (per_orbit[static_cast<std::size_t>(j)][idx::kDlambda] - per_orbit[0][idx::kDlambda]);
    const double drift_linear = chief.a * (predicted[idx::kDlambda] - escape->roe_after[idx::kDlambda]);
    worst = std::max(worst, std::abs(drift_numeric - drift_linear));
    RecordProperty("numeric_drift_orbit" + std::to_string(j), std::to_string(drift_numeric));
    // issue text 47 m per orbit; measured regression bound: 0.17 m per orbit (0.51 m after 3 orbits) (2026-11); bound 0.5 m per orbit
    EXPECT_NEAR(drift_numeric, j * 47.0, j * 0.5);
  }
  RecordProperty("numeric_vs_linear_drift_worst_m", std::to_string(worst));
  // measured regression bound: 0.021 m (2026-11); bound 0.2 m
  EXPECT_LT(worst, 0.2);
  // target a*da = -5 m; measured regression bound: 3.6e-4 m (2026-11); bound 0.02 m
  EXPECT_NEAR(chief.a * per_orbit[0][idx::kDa], -5.0, 0.02);
  RecordProperty("numeric_rn_min_m", std::to_string(rn_min));
  // requirement: epsilon = 5 m (docs/conventions.md Safety); measured 18.1 m (2026-11)
  EXPECT_GT(rn_min, EscapeSettings{}.epsilon_m);
}

// No single impulse below 10 m/s can make a 100 km-safe orbit from the science orbit: the
// planner reports it (field "escape") instead of returning an unsafe maneuver.
TEST(EscapeManeuver, NoSafeCandidateIsAnError) {
  const auto chief = mission_chief();
  EscapeSettings s;
  s.epsilon_m = 1e5;
  s.search_window_orbits = 0.05;
  const auto escape = plan_escape(chief, science_roe(chief.a), RoeCovariance::Zero(), 0.0, s);
  ASSERT_FALSE(escape.ok());
  EXPECT_EQ(escape.error().field, "escape");
}

TEST(EscapeManeuver, BadInputNamesTheField) {
  const auto chief = mission_chief();
  const RelativeOrbitalElements roe = science_roe(chief.a);
  EXPECT_EQ(plan_escape(chief, roe, RoeCovariance::Zero(), std::nan(""), EscapeSettings{}).error().field, "t_earliest");
  EXPECT_EQ(plan_escape(chief, roe, RoeCovariance::Zero(), -1.0, EscapeSettings{}).error().field, "t_earliest");
  EscapeSettings s;
  s.da_target_m = 0.0;
  EXPECT_EQ(plan_escape(chief, roe, RoeCovariance::Zero(), 0.0, s).error().field, "da_target_m");
  s = EscapeSettings{};
  s.psi_samples = 1;
  EXPECT_EQ(plan_escape(chief, roe, RoeCovariance::Zero(), 0.0, s).error().field, "psi_samples");
  RelativeOrbitalElements nan_roe = roe;
  nan_roe[0] = std::nan("");
  EXPECT_EQ(plan_escape(chief, nan_roe, RoeCovariance::Zero(), 0.0, EscapeSettings{}).error().field, "roe");
  RoeCovariance not_psd = RoeCovariance::Zero();
  not_psd(2, 2) = -1e-12;
  EXPECT_EQ(plan_escape(chief, roe, not_psd, 0.0, EscapeSettings{}).error().field, "covariance");
  auto bad_chief = chief;
  bad_chief.a = -1.0;
  EXPECT_EQ(plan_escape(bad_chief, roe, RoeCovariance::Zero(), 0.0, EscapeSettings{}).error().field, "chief.a");
}

}  // namespace
}  // namespace visors::safety
