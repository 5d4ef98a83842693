// Orbit propagation: conservation laws, J2 secular theory, RK4 against the reference
// integrator, maneuvers, event landing and bad input.

#include <cmath>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/earth_frames.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/orbit_propagator.hpp"

namespace visors::dynamics {
namespace {

using core::GpsTime;

const GpsTime kEpoch = GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();

// The mission chief (Guffanti et al., AAS 23-149, 2023, Table 5: a = R_E + 500 km, e = 0.004,
// i = 97.8 deg, RAAN 157.5 deg; argument of perigee 90 deg and M = 0 are this test's choice).
astro::KeplerianElements mission_chief() {
  return {6378136.3 + 500e3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad, 90.0 * core::kDegToRad, 0.0};
}

ForceModel make_forces(const ForceModelConfig& config) {
  auto forces = files::load_force_model(config, SpacecraftProperties{});
  EXPECT_TRUE(forces.ok()) << forces.error().describe();
  return std::move(forces).value();
}

OrbitPropagator make_propagator(ForceModel& forces, const PropagatorSettings& settings) {
  auto p = OrbitPropagator::create(forces, settings);
  EXPECT_TRUE(p.ok()) << p.error().describe();
  return std::move(p).value();
}

PropagatorSettings reference_settings() {
  PropagatorSettings s;
  s.integrator = IntegratorKind::kDormandPrince87;
  return s;
}

PropagatorSettings rk4_settings(double step, IntegratorKind kind = IntegratorKind::kRk4Dynamic) {
  PropagatorSettings s;
  s.integrator = kind;
  s.step_s = step;
  s.min_step_s = std::min(1.0, step);
  return s;
}

double energy(const core::StateVector& x, double gm) { return 0.5 * x.v.squaredNorm() - gm / x.r.norm(); }

// Propagator acceptance (docs/algorithms/dynamics.md#propagator-acceptance): two-body energy and
// angular momentum conserved to 1e-10 (relative) over 10 days with the reference integrator.
TEST(OrbitPropagator, TwoBodyConservesEnergyAndAngularMomentumOverTenDays) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, reference_settings());
  const core::StateVector x0 = astro::cartesian_from_keplerian(mission_chief(), forces.gm());
  const auto x1 = propagator.propagate_to(kEpoch, x0, kEpoch + 10.0 * 86400.0);
  ASSERT_TRUE(x1.ok()) << x1.error().describe();
  const double e0 = energy(x0, forces.gm());
  const Eigen::Vector3d h0 = x0.r.cross(x0.v);
  const double energy_drift = std::abs(energy(x1.value(), forces.gm()) / e0 - 1.0);
  const double momentum_drift = (x1.value().r.cross(x1.value().v) - h0).norm() / h0.norm();
  std::printf("10-day two-body drift: energy %.2e, angular momentum %.2e\n", energy_drift, momentum_drift);
  // the acceptance bound (1e-10, above); loose vs measurement: 4.3e-14 / 2.1e-14 (2026-11), ~2000x below the bound
  EXPECT_LT(energy_drift, 1e-10);
  EXPECT_LT(momentum_drift, 1e-10);
}

// Two-body motion against Kepler's equation (astro::propagate_kepler), one day.
TEST(OrbitPropagator, TwoBodyMatchesKeplerOverOneDay) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, reference_settings());
  const astro::KeplerianElements k0 = mission_chief();
  const auto x1 = propagator.propagate_to(kEpoch, astro::cartesian_from_keplerian(k0, forces.gm()), kEpoch + 86400.0);
  ASSERT_TRUE(x1.ok());
  const core::StateVector expected =
      astro::cartesian_from_keplerian(astro::propagate_kepler(k0, 86400.0, forces.gm()), forces.gm());
  // loose: measured 2.7e-6 m (2026-11), bound 1e-3 ~400x above
  EXPECT_LT((x1.value().r - expected.r).norm(), 1e-3);  // [m]
}

// Propagator acceptance: J2-only secular rates of RAAN and argument of latitude match first-order
// theory (Brouwer/Kozai; astro::j2_secular_rates). Numerical osculating states -> mean elements
// (astro::mean_from_osculating) at both ends of one day; the field's own C20 gives J2 = -sqrt(5) C20.
// The elements are taken in an inertial frame whose z axis is the Earth's (the CIP, 0.14 deg from
// the GCRF pole in 2024): for a near-polar orbit the J2 rates scale with cos i = -0.136, so
// measuring i from the GCRF equator instead would shift them by up to 2 %.
TEST(OrbitPropagator, J2OnlySecularRatesMatchFirstOrderTheory) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(2, 0));
  OrbitPropagator propagator = make_propagator(forces, reference_settings());
  // J2 = -sqrt(5) C20 of the field the force model loaded (the file, or the embedded fallback).
  const auto file = files::load_gravity_field(forces.config().gravity.model, 2);
  const GravityField field = file.ok() ? file.value() : embedded_gravity_field();
  const core::EarthGravityConstants earth{field.gm, field.radius, -std::sqrt(5.0) * field.c(2, 0)};
  const astro::KeplerianElements mean0 = mission_chief();
  const double duration = 86400.0;  // [s]
  const auto osc0 = astro::osculating_from_mean(mean0, earth);
  ASSERT_TRUE(osc0.ok());
  const Eigen::Vector3d pole = core::gcrf_to_itrf_matrix(kEpoch, {}).row(2).transpose();
  const Eigen::Vector3d x_axis = (Eigen::Vector3d::UnitX() - pole.x() * pole).normalized();
  Eigen::Matrix3d to_pole_frame;  // GCRF -> inertial frame with z along the Earth's pole
  to_pole_frame << x_axis.transpose(), pole.cross(x_axis).transpose(), pole.transpose();
  const core::StateVector x0_pole = astro::cartesian_from_keplerian(osc0.value(), earth.mu);
  const core::StateVector x0{to_pole_frame.transpose() * x0_pole.r, to_pole_frame.transpose() * x0_pole.v};
  // Mean elements every 10 min; least-squares slopes of the unwrapped RAAN and argument of
  // latitude. The theory is evaluated at the run's average mean elements: the first-order
  // mean<->osculating map leaves ~30 m (J2^2) in the mean a, which alone would shift n by 5e-9 rad/s.
  std::vector<GpsTime> outputs;
  for (double t = 0.0; t <= duration; t += 600.0) outputs.push_back(kEpoch + t);
  std::vector<double> times, raan, u;
  astro::KeplerianElements average{};
  ASSERT_TRUE(propagator.propagate(kEpoch, x0, outputs, {}, [&](GpsTime t, const core::StateVector& x) {
    const auto osc = astro::cartesian_to_keplerian(to_pole_frame * x.r, to_pole_frame * x.v, earth.mu);
    const auto mean = astro::mean_from_osculating(osc.value(), earth);
    const double dt = t.seconds_since(kEpoch);
    const auto unwrap = [](const std::vector<double>& series, double angle) {
      return series.empty() ? angle : series.back() + std::remainder(angle - series.back(), core::kTwoPi);
    };
    raan.push_back(unwrap(raan, mean.value().raan));
    u.push_back(unwrap(u, mean.value().argp + mean.value().M));
    times.push_back(dt);
    average.a += mean.value().a;
    average.e += mean.value().e;
    average.i += mean.value().i;
  }).ok());
  const double count = static_cast<double>(times.size());
  average.a /= count;
  average.e /= count;
  average.i /= count;
  const auto slope = [&](const std::vector<double>& y) {
    double st = 0, sy = 0, stt = 0, sty = 0;
    for (std::size_t k = 0; k < y.size(); ++k) {
      st += times[k];
      sy += y[k];
      stt += times[k] * times[k];
      sty += times[k] * y[k];
    }
    return (count * sty - st * sy) / (count * stt - st * st);
  };
  const astro::J2SecularRates rates = astro::j2_secular_rates(average, earth);
  const double raan_rate = slope(raan);
  const double u_j2_rate = slope(u) - rates.n;  // the J2 part of du/dt
  const double u_j2_theory = rates.argp_dot + rates.M_dot - rates.n;
  std::printf("J2 RAAN rate %.6e rad/s (theory %.6e); J2 part of du/dt %.6e (theory %.6e)\n", raan_rate,
              rates.raan_dot, u_j2_rate, u_j2_theory);
  // First-order theory: the neglected J2^2 terms are ~1e-3 of the J2 rates.
  // measured 1.8e-10 / 2.6e-9 rad/s (2026-11) vs bounds 4.2e-10 / 2.9e-9 (u: within 1.1x, close to failing)
  EXPECT_NEAR(raan_rate, rates.raan_dot, 2e-3 * std::abs(rates.raan_dot));
  EXPECT_NEAR(u_j2_rate, u_j2_theory, 2e-3 * std::abs(u_j2_theory));
}

// Propagator acceptance: RK4 at the truth's step against the reference integrator over one day,
// with every truth force (GGM05S 60x60, NRLMSISE-00 drag, SRP with penumbra, Sun, Moon). The
// activity is the observed one in NRLMSISE-00's daily-Ap mode, constant over the day: with the
// 3-hourly ap history (the truth's default) the drag jumps every 3 hours by up to tens of percent,
// and both integrators cross each jump with an error of order (jump x step) that is not the
// truncation error this test bounds (measured 10.3 mm vs 1.9 mm daily, 2026-11).
TEST(OrbitPropagator, Rk4AtTheTruthStepMatchesTheReferenceOverOneDay) {
  ForceModelConfig config = ForceModelConfig::truth();
  config.drag.ap_history = false;
  ForceModel forces = make_forces(config);
  const core::StateVector x0 = astro::cartesian_from_keplerian(mission_chief(), forces.gm());
  const GpsTime t1 = kEpoch + 86400.0;
  OrbitPropagator reference = make_propagator(forces, reference_settings());
  const auto x_ref = reference.propagate_to(kEpoch, x0, t1);
  ASSERT_TRUE(x_ref.ok()) << x_ref.error().describe();
  OrbitPropagator rk4 = make_propagator(forces, rk4_settings(2.0));
  const auto x_rk4 = rk4.propagate_to(kEpoch, x0, t1);
  ASSERT_TRUE(x_rk4.ok());
  const double error = (x_rk4.value().r - x_ref.value().r).norm();
  std::printf("one day, truth forces: RK4 2 s vs DP8(7): %.2f mm (%lld RK4 steps, %lld reference steps)\n",
              1e3 * error, static_cast<long long>(rk4.stats().steps),
              static_cast<long long>(reference.stats().steps));
  // measured 1.9e-3 m with NRLMSISE-00 (2.6e-3 m with the Harris-Priester maximum), 2026-11
  EXPECT_LT(error, 0.01);  // [m], the acceptance bound (docs/algorithms/dynamics.md#propagator-acceptance)
}

// A maneuver at t equals stopping at t, adding dv (RTN of the pre-burn state) and restarting.
TEST(OrbitPropagator, ImpulsiveManeuverEqualsStopAddRestart) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(4, 4));
  OrbitPropagator propagator = make_propagator(forces, rk4_settings(10.0));
  const core::StateVector x0 = astro::cartesian_from_keplerian(mission_chief(), forces.gm());
  const GpsTime t_burn = kEpoch + 1234.567;
  const GpsTime t_end = kEpoch + 3000.0;
  const Eigen::Vector3d dv_rtn(0.001, 0.02, -0.003);  // [m/s]
  const ImpulsiveManeuver burn{t_burn, dv_rtn, ManeuverFrame::kRtn};
  const auto with_burn = propagator.propagate_to(kEpoch, x0, t_end, std::span(&burn, 1));
  ASSERT_TRUE(with_burn.ok());
  auto at_burn = propagator.propagate_to(kEpoch, x0, t_burn);
  ASSERT_TRUE(at_burn.ok());
  core::StateVector restarted = at_burn.value();
  restarted.v += core::gcrf_to_rtn_matrix(restarted).transpose() * dv_rtn;
  const auto manual = propagator.propagate_to(t_burn, restarted, t_end);
  ASSERT_TRUE(manual.ok());
  // measured 0 m (2026-11)
  EXPECT_LT((with_burn.value().r - manual.value().r).norm(), 1e-6);  // [m]: same steps, round-off
}

// Outputs land exactly on requested times, including ones off the step grid, and the state at a
// maneuver time is the post-burn state.
TEST(OrbitPropagator, OutputsLandExactlyOnRequestedTimes) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(2, 0));
  for (const IntegratorKind kind : {IntegratorKind::kRk4Fixed, IntegratorKind::kRk4Dynamic,
                                    IntegratorKind::kDormandPrince87}) {
    PropagatorSettings settings = rk4_settings(10.0, kind);
    OrbitPropagator propagator = make_propagator(forces, settings);
    const std::vector<GpsTime> outputs = {kEpoch, kEpoch + 3.3, kEpoch + 25.0, kEpoch + 25.0 + 1e-9, kEpoch + 100.0};
    const ImpulsiveManeuver burn{kEpoch + 25.0, {0.0, 1.0, 0.0}, ManeuverFrame::kRtn};
    std::vector<GpsTime> seen;
    std::vector<core::StateVector> states;
    const auto result = propagator.propagate(
        kEpoch, astro::cartesian_from_keplerian(mission_chief(), forces.gm()), outputs, std::span(&burn, 1),
        [&](GpsTime t, const core::StateVector& x) {
          seen.push_back(t);
          states.push_back(x);
        });
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(seen, outputs) << "integrator " << static_cast<int>(kind);
    // Post-burn at 25 s: the next output 1 ns later has practically the same velocity.
    // loose: measured 8.5e-9 m/s (2026-11), bound 1e-6 ~120x above
    EXPECT_NEAR((states[3].v - states[2].v).norm(), 0.0, 1e-6);
  }
}

// The dynamic step never takes a step shorter than min_step between distant events: 25 s with
// a 10 s step and 1 s minimum is 10 + 7.5 + 7.5 (the last 15 s split in two), not 10 + 10 + 5.
TEST(OrbitPropagator, DynamicStepSplitsTheRemainderEvenly) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  PropagatorSettings settings = rk4_settings(10.0);
  settings.min_step_s = 6.0;
  OrbitPropagator propagator = make_propagator(forces, settings);
  ASSERT_TRUE(propagator.propagate_to(kEpoch, astro::cartesian_from_keplerian(mission_chief(), forces.gm()),
                                      kEpoch + 25.0).ok());
  EXPECT_EQ(propagator.stats().steps, 3);
}

TEST(OrbitPropagator, RejectsUnsortedOutputs) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, rk4_settings(10.0));
  const std::vector<GpsTime> outputs = {kEpoch + 20.0, kEpoch + 10.0};
  const auto r = propagator.propagate(kEpoch, astro::cartesian_from_keplerian(mission_chief(), forces.gm()),
                                      outputs, {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "outputs");
}

TEST(OrbitPropagator, RejectsAPositionInsideTheEarth) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, rk4_settings(10.0));
  const auto r = propagator.propagate_to(kEpoch, {{1e6, 0, 0}, {0, 7e3, 0}}, kEpoch + 10.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "state.r");
}

TEST(OrbitPropagator, ReportsReentryInsteadOfIntegratingThroughTheEarth) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, rk4_settings(10.0));
  // Falling straight down from 200 km altitude.
  const auto r = propagator.propagate_to(kEpoch, {{6.578e6, 0, 0}, {-2e3, 100.0, 0}}, kEpoch + 3600.0);
  ASSERT_FALSE(r.ok());
  EXPECT_NE(r.error().message.find("below the Earth's surface"), std::string::npos);
}

TEST(OrbitPropagator, RejectsANonFiniteState) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  OrbitPropagator propagator = make_propagator(forces, rk4_settings(10.0));
  const auto r = propagator.propagate_to(kEpoch, {{7e6, 0, NAN}, {0, 7e3, 0}}, kEpoch + 10.0);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "state");
}

TEST(OrbitPropagator, RejectsANonPositiveStep) {
  ForceModel forces = make_forces(ForceModelConfig::gravity_only(0, 0));
  EXPECT_EQ(OrbitPropagator::create(forces, rk4_settings(0.0)).error().field, "step_s");
}

}  // namespace
}  // namespace visors::dynamics
