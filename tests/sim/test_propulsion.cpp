#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"
#include "visors/sim/propulsion.hpp"

namespace {

using visors::sim::Propulsion;
using visors::sim::PropulsionSettings;
using visors::sim::RandomStream;

constexpr double kMass = 10.62;       // OSC wet mass [kg] (docs/conventions.md)
constexpr double kPropellant = 0.25;  // test value [kg]

PropulsionSettings ideal_settings() {
  PropulsionSettings s;
  s.magnitude_sigma = 0.0;
  s.direction_sigma_rad = 0.0;
  s.isp_sigma_s = 0.0;
  return s;
}

Propulsion make(const PropulsionSettings& s, std::uint64_t seed = 1) {
  auto p = Propulsion::create(s, kMass, kPropellant, RandomStream(seed, "osc.propulsion"));
  EXPECT_TRUE(p.ok());
  return std::move(p).value();
}

// Velocity change [m/s] along +X whose impulse at the current mass is `impulse_ns`.
Eigen::Vector3d dv_for(const Propulsion& p, double impulse_ns) { return {impulse_ns / p.mass_kg(), 0.0, 0.0}; }

TEST(Propulsion, DefaultSettingsAreValid) { EXPECT_TRUE(PropulsionSettings{}.validate().ok()); }

TEST(Propulsion, ValidateNamesTheField) {
  PropulsionSettings s;
  s.magnitude_sigma = 0.6;  // outside [0, 0.5] (paper's Table 1(b): 0.05 .. 0.5)
  EXPECT_EQ(s.validate().error().field, "magnitude_sigma");
}

TEST(Propulsion, CreateRejectsPropellantAboveMass) {
  auto p = Propulsion::create({}, kMass, kMass, RandomStream(1, "x"));
  EXPECT_EQ(p.error().field, "propellant_kg");
}

// The quantised impulse is an exact integer multiple of 6e-5 N s (paper table): the model builds
// it as n * quantum, so the equality holds bit for bit.
TEST(Propulsion, ImpulseIsAnExactMultipleOfTheQuantum) {
  Propulsion p = make(PropulsionSettings{});
  for (int k = 0; k < 20; ++k) {
    const double requested_ns = 1.1e-3 + 1.03e-3 * k;  // off-grid requests 1.1e-3 .. 2.07e-2 N s
    auto e = p.execute(100.0 * k, dv_for(p, requested_ns));
    ASSERT_TRUE(e.ok());
    const double steps = std::round(e->impulse_ns / 6.0e-5);
    EXPECT_EQ(e->impulse_ns, steps * 6.0e-5);
  }
}

// Rounding to the nearest quantum: 2.0e-3 N s = 33.33 quanta -> 33 * 6e-5 = 1.98e-3 N s (hand).
TEST(Propulsion, ImpulseRoundsToTheNearestQuantum) {
  Propulsion p = make(PropulsionSettings{});
  // n x quantum (hand, comment above); loose: measured 0 (2026-11), bound 1e-15 N s ~2300x above round-off (ulp 4.3e-19 N s)
  EXPECT_NEAR(p.execute(0.0, dv_for(p, 2.0e-3))->impulse_ns, 1.98e-3, 1e-15);
}

// 9.9e-4 N s rounds to 17 quanta = 1.02e-3 N s >= 1e-3 (accepted); 9.5e-4 rounds to 16 quanta =
// 9.6e-4 < 1e-3 (rejected). Hand arithmetic on the paper's numbers.
TEST(Propulsion, RejectsBelowMinimumAfterRounding) {
  Propulsion p = make(PropulsionSettings{});
  EXPECT_EQ(p.execute(0.0, dv_for(p, 9.5e-4)).error().field, "dv_commanded_body_mps");
}

TEST(Propulsion, AcceptsJustBelowMinimumThatRoundsUp) {
  Propulsion p = make(PropulsionSettings{});
  // n x quantum (hand, comment above); loose: measured 0 (2026-11), bound 1e-15 N s ~4600x above round-off (ulp 2.2e-19 N s)
  EXPECT_NEAR(p.execute(0.0, dv_for(p, 9.9e-4))->impulse_ns, 1.02e-3, 1e-15);
}

TEST(Propulsion, RejectsAboveMaximum) {
  Propulsion p = make(PropulsionSettings{});
  EXPECT_EQ(p.execute(0.0, dv_for(p, 2.3e-2)).error().field, "dv_commanded_body_mps");
}

// The maximum itself (366.67 quanta) is executed as 366 * 6e-5 = 2.196e-2 N s (hand), the largest
// multiple not above 2.2e-2.
TEST(Propulsion, MaximumImpulseIsClampedToTheLastQuantum) {
  Propulsion p = make(PropulsionSettings{});
  // n x quantum (hand, comment above); loose: measured 0 (2026-11), bound 1e-15 N s ~290x above round-off (ulp 3.5e-18 N s)
  EXPECT_NEAR(p.execute(0.0, dv_for(p, 2.2e-2))->impulse_ns, 2.196e-2, 1e-15);
}

TEST(Propulsion, RejectsZeroCommand) {
  Propulsion p = make(PropulsionSettings{});
  EXPECT_EQ(p.execute(0.0, Eigen::Vector3d::Zero()).error().field, "dv_commanded_body_mps");
}

TEST(Propulsion, RejectsNonFiniteCommand) {
  Propulsion p = make(PropulsionSettings{});
  EXPECT_EQ(p.execute(0.0, {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}).error().field, "dv_commanded_body_mps");
}

TEST(Propulsion, RejectsNonFiniteTime) {
  Propulsion p = make(PropulsionSettings{});
  EXPECT_EQ(p.execute(std::numeric_limits<double>::infinity(), dv_for(p, 5e-3)).error().field, "t_s");
}

// 46.5 s between impulses (paper table): 46.4 s later is rejected, 46.5 s later accepted.
TEST(Propulsion, RejectsImpulsesCloserThanTheSpacing) {
  Propulsion p = make(PropulsionSettings{});
  ASSERT_TRUE(p.execute(10.0, dv_for(p, 5e-3)).ok());
  EXPECT_EQ(p.execute(56.4, dv_for(p, 5e-3)).error().field, "t_s");
}

TEST(Propulsion, AcceptsImpulsesExactlyOneSpacingApart) {
  Propulsion p = make(PropulsionSettings{});
  ASSERT_TRUE(p.execute(10.1, dv_for(p, 5e-3)).ok());
  EXPECT_TRUE(p.execute(56.6, dv_for(p, 5e-3)).ok());
}

TEST(Propulsion, RejectedCommandDoesNotMoveTheLastImpulseTime) {
  Propulsion p = make(PropulsionSettings{});
  ASSERT_TRUE(p.execute(10.0, dv_for(p, 5e-3)).ok());
  ASSERT_FALSE(p.execute(20.0, dv_for(p, 5e-3)).ok());
  EXPECT_EQ(p.last_impulse_t(), 10.0);
}

// With every error switched off the executed velocity change is the command (chosen on the
// quantum grid: 50 quanta), to round-off of the impulse/mass division (1e-16 m/s on 2.8e-4 m/s).
TEST(Propulsion, ZeroErrorsReproduceTheCommand) {
  Propulsion p = make(ideal_settings());
  const Eigen::Vector3d dv_body = (50 * 6.0e-5 / kMass) * Eigen::Vector3d(1.0, -2.0, 2.0) / 3.0;
  auto e = p.execute(0.0, dv_body);
  ASSERT_TRUE(e.ok());
  EXPECT_LT((e->dv_executed_body_mps - dv_body).norm(), 1e-16);
}

TEST(Propulsion, ZeroIspSigmaGivesTheNominalIsp) { EXPECT_EQ(make(ideal_settings()).isp_s(), 44.0); }

// Mass depletion against the rocket equation by hand: the 2e-2 N s request is quantised to
// 333 * 6e-5 = 1.998e-2 N s; on 10.62 kg dv = 1.998e-2 / 10.62 = 1.881356e-3 m/s and
// dm = 10.62 (1 - exp(-dv / (44 * 9.80665))) = 4.630e-5 kg (= J / (Isp g0) to first order).
// Tolerance 1e-14 kg: the cancellation in 1 - exp(-x), x = 4.4e-6, costs ~1e-15 kg in the reference.
TEST(Propulsion, PropellantUseFollowsTsiolkovsky) {
  Propulsion p = make(ideal_settings());
  auto e = p.execute(0.0, dv_for(p, 2.0e-2));  // 333.33 quanta -> 333 * 6e-5 = 1.998e-2 N s
  const double dv = 1.998e-2 / kMass;
  const double dm = kMass * (1.0 - std::exp(-dv / (44.0 * 9.80665)));
  EXPECT_NEAR(e->propellant_used_kg, dm, 1e-14);
}

TEST(Propulsion, MassAndPropellantDecreaseByTheUsedPropellant) {
  Propulsion p = make(ideal_settings());
  auto e = p.execute(0.0, dv_for(p, 2.0e-2));
  // the same used mass taken off both, round-off (ulp 1.8e-15 / 5.6e-17 kg); measured 0 (2026-11)
  EXPECT_NEAR(p.mass_kg() + e->propellant_used_kg, kMass, 1e-15);
  EXPECT_NEAR(p.propellant_kg() + e->propellant_used_kg, kPropellant, 1e-15);
}

// Exhaustion: with 1e-5 kg left a 2e-2 N s command (needs 4.6e-5 kg) fires what is left,
// dv = Isp g0 ln(m / (m - 1e-5)) = 4.06e-4 m/s (rocket equation; tolerance 1e-12 m/s covers the
// round-off of the ratio inside the logarithm), and the next command is rejected.
TEST(Propulsion, LastImpulseFiresWhatIsLeft) {
  auto created = Propulsion::create(ideal_settings(), kMass, 1.0e-5, RandomStream(1, "x"));
  Propulsion p = std::move(created).value();
  auto e = p.execute(0.0, dv_for(p, 2.0e-2));
  EXPECT_NEAR(e->dv_executed_body_mps.x(), 44.0 * 9.80665 * std::log(kMass / (kMass - 1.0e-5)), 1e-12);
  EXPECT_EQ(p.propellant_kg(), 0.0);
}

TEST(Propulsion, RejectsWhenPropellantIsExhausted) {
  auto created = Propulsion::create(ideal_settings(), kMass, 1.0e-5, RandomStream(1, "x"));
  Propulsion p = std::move(created).value();
  ASSERT_TRUE(p.execute(0.0, dv_for(p, 2.0e-2)).ok());
  EXPECT_EQ(p.execute(100.0, dv_for(p, 2.0e-2)).error().field, "dv_commanded_body_mps");
}

// Statistics over N = 20000 impulses of 1e-2 N s along a fixed direction; references are the
// model's distributions (file comment of propulsion.hpp) with 5-standard-error bands.
struct ErrorSamples {
  double magnitude_mean = 0.0, magnitude_std = 0.0;  // of |dv_exec| / |dv_quantised| - 1
  double angle_sq_mean = 0.0;                        // of the angle^2 between executed and commanded [rad^2]
  Eigen::Vector3d unit_mean = Eigen::Vector3d::Zero();  // of the executed unit vector
};
constexpr int kDraws = 20000;

ErrorSamples sample_errors(double magnitude_sigma, double direction_sigma_rad) {
  PropulsionSettings s;
  s.magnitude_sigma = magnitude_sigma;
  s.direction_sigma_rad = direction_sigma_rad;
  s.spacing_s = 0.0;
  auto created = Propulsion::create(s, kMass, 0.9 * kMass, RandomStream(99, "stats"));
  Propulsion p = std::move(created).value();
  const Eigen::Vector3d u = Eigen::Vector3d(2.0, -1.0, 0.5).normalized();
  ErrorSamples out;
  double sum = 0.0, sum2 = 0.0, angle2 = 0.0;
  for (int k = 0; k < kDraws; ++k) {
    const double mass = p.mass_kg();
    auto e = p.execute(k, u * (1.0e-2 / mass));
    const double nominal = e->impulse_ns / mass;
    const double f = e->dv_executed_body_mps.norm() / nominal - 1.0;
    sum += f;
    sum2 += f * f;
    const Eigen::Vector3d w = e->dv_executed_body_mps.normalized();
    const double angle = std::atan2(w.cross(u).norm(), w.dot(u));
    angle2 += angle * angle;
    out.unit_mean += w / kDraws;
  }
  out.magnitude_mean = sum / kDraws;
  out.magnitude_std = std::sqrt(sum2 / kDraws - out.magnitude_mean * out.magnitude_mean);
  out.angle_sq_mean = angle2 / kDraws;
  return out;
}

// Mean of N(0, 0.2): |mean| < 5 sigma / sqrt(N).
TEST(Propulsion, MagnitudeErrorIsUnbiased) {
  EXPECT_LT(std::abs(sample_errors(0.2, 0.0).magnitude_mean), 5.0 * 0.2 / std::sqrt(kDraws));
}

// Standard deviation of N(0, 0.2): standard error of the sample std ~ sigma / sqrt(2N).
TEST(Propulsion, MagnitudeErrorHasTheConfiguredSigma) {
  EXPECT_NEAR(sample_errors(0.2, 0.0).magnitude_std, 0.2, 5.0 * 0.2 / std::sqrt(2.0 * kDraws));
}

// Angle = |theta|, theta ~ N(0, sigma): E[angle^2] = sigma^2, Var[angle^2] = 2 sigma^4.
TEST(Propulsion, DirectionErrorHasTheConfiguredRmsAngle) {
  const double sigma = 2.0 * visors::core::kDegToRad;
  EXPECT_NEAR(sample_errors(0.0, sigma).angle_sq_mean, sigma * sigma,
              5.0 * std::sqrt(2.0) * sigma * sigma / std::sqrt(kDraws));
}

// Isotropy about the command: the mean executed unit vector has no perpendicular component beyond
// 5 standard errors (each perpendicular coordinate has std ~ sigma / sqrt(2)).
TEST(Propulsion, DirectionErrorIsIsotropicAboutTheCommand) {
  const double sigma = 2.0 * visors::core::kDegToRad;
  const Eigen::Vector3d u = Eigen::Vector3d(2.0, -1.0, 0.5).normalized();
  const Eigen::Vector3d m = sample_errors(0.0, sigma).unit_mean;
  EXPECT_LT((m - m.dot(u) * u).norm(), 5.0 * std::sqrt(2.0) * (sigma / std::sqrt(2.0)) / std::sqrt(kDraws));
}

// Determinism: the same seed gives bit-identical executed impulses and Isp.
TEST(Propulsion, SameSeedGivesIdenticalResults) {
  Propulsion a = make(PropulsionSettings{}, 5), b = make(PropulsionSettings{}, 5);
  ASSERT_EQ(a.isp_s(), b.isp_s());
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d dv(1e-3, -5e-4, 2e-4 * k / 50.0);
    auto ea = a.execute(50.0 * k, dv), eb = b.execute(50.0 * k, dv);
    ASSERT_EQ(ea->dv_executed_body_mps, eb->dv_executed_body_mps);
    ASSERT_EQ(ea->propellant_used_kg, eb->propellant_used_kg);
  }
}

TEST(Propulsion, DifferentSeedsGiveDifferentIsp) {
  EXPECT_NE(make(PropulsionSettings{}, 5).isp_s(), make(PropulsionSettings{}, 6).isp_s());
}

// Paper's budget metric: |1| + |-2| + |3| = 6.
// Nozzle biases (step 4): drawn once per run, one per nozzle, each scaling the component it fires.
PropulsionSettings biased_settings() {
  PropulsionSettings s = ideal_settings();
  s.magnitude_bias_sigma = 0.1;
  s.spacing_s = 0.0;
  return s;
}

TEST(Propulsion, NozzleBiasScalesItsComponentEveryTime) {
  // A +X command fires the +X nozzle only: executed / commanded = 1 + b(+X) on every impulse.
  Propulsion p = make(biased_settings());
  const double b = p.nozzle_bias()[0];
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d dv = dv_for(p, 50 * 6.0e-5);
    auto e = p.execute(k, dv);
    ASSERT_TRUE(e.ok());
    EXPECT_NEAR(e->dv_executed_body_mps.x() / dv.x(), 1.0 + b, 1e-12) << k;
  }
}

TEST(Propulsion, OppositeNozzlesHaveTheirOwnBias) {
  // A -Y command fires the -Y nozzle (index 4).
  Propulsion p = make(biased_settings());
  const Eigen::Vector3d dv(0.0, -50 * 6.0e-5 / kMass, 0.0);
  auto e = p.execute(0.0, dv);
  ASSERT_TRUE(e.ok());
  EXPECT_NEAR(e->dv_executed_body_mps.y() / dv.y(), 1.0 + p.nozzle_bias()[4], 1e-12);
}

TEST(Propulsion, NozzleBiasesHaveTheirSigma) {
  // Six per run over 2000 runs: the sample std of N(0, 0.1) within 5 standard errors.
  double sum = 0.0, sum2 = 0.0;
  constexpr int runs = 2000;
  for (int k = 0; k < runs; ++k) {
    const Propulsion p = make(biased_settings(), static_cast<std::uint64_t>(k + 1));
    for (double b : p.nozzle_bias()) {
      sum += b;
      sum2 += b * b;
    }
  }
  const double n = 6.0 * runs;
  const double mean = sum / n;
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.1, 5.0 * 0.1 / std::sqrt(2.0 * n));
}

TEST(Propulsion, ZeroBiasSigmaGivesNoBias) {
  const Propulsion p = make(ideal_settings());
  for (double b : p.nozzle_bias()) EXPECT_EQ(b, 0.0);
}

TEST(Propulsion, BiasSigmaOutOfRangeIsNamed) {
  PropulsionSettings s;
  s.magnitude_bias_sigma = 0.6;
  EXPECT_EQ(s.validate().error().field, "magnitude_bias_sigma");
}

TEST(Propulsion, ThrusterL1NormSumsAbsoluteComponents) {
  EXPECT_EQ(visors::sim::thruster_l1_norm({1.0, -2.0, 3.0}), 6.0);
}

}  // namespace
