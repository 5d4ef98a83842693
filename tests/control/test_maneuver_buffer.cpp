// Maneuver buffering: actuator limits of every piece, the net ROE effect, and the effect in a
// numerical J2 propagation (independent of the linear model the buffer solves in).

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/control/impulse_effect.hpp"
#include "control/j2_numerical_propagation.hpp"
#include "visors/control/maneuver_buffer.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"

namespace visors::control {
namespace {

// Mission chief (mean, t = 0) and the optics spacecraft's wet mass (Guffanti et al., AAS 23-149,
// 2023, Tables 5 and 4).
const astro::KeplerianElements kChief{6878136.3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad,
                                      90.0 * core::kDegToRad, 0.0};
constexpr double kMass = 10.62;  // [kg]
// A large impulse to buffer: (10, 50, 20) mm/s (dozens of pieces; the loss of an equal split is
// metres, docs/algorithms/control.md#maneuver-buffering).
const Impulse kLargeImpulse{2000.0, {0.010, 0.050, 0.020}};

// Net first-order effect of impulses on the mean ROE at t_ref.
astro::RelativeOrbitalElements effect_of(const std::vector<Impulse>& impulses, double t_ref) {
  return predict_roe(kChief, astro::RelativeOrbitalElements::Zero(), impulses, t_ref);
}

TEST(ManeuverBuffer, EveryPieceIsWithinTheActuatorLimits) {
  const auto buffered = buffer_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(buffered.ok()) << buffered.error().describe();
  const ActuatorLimits limits;
  for (const Impulse& p : buffered->pieces) {
    const double impulse = kMass * p.dv_rtn.norm();  // [N s]
    // actuator limits 1e-3 .. 2.2e-2 N s, quantum 6e-5 N s (docs/conventions.md Propulsion), round-off slack; measured 0.0161 .. 0.0213 N s, quantum residual 1.1e-13 (2026-11)
    EXPECT_LE(impulse, limits.max_impulse_ns + 1e-15);
    EXPECT_GE(impulse, limits.min_impulse_ns - 1e-15);
    EXPECT_NEAR(impulse / limits.quantum_ns, std::round(impulse / limits.quantum_ns), 1e-9);
  }
}

// Pieces 46.5 s apart, centred on the planned time (a one-sided schedule adds 3 N dt dv_T of
// dlambda: docs/algorithms/control.md#maneuver-buffering).
TEST(ManeuverBuffer, PiecesAreEvenlySpacedAndCentredOnThePlannedTime) {
  const auto pieces = split_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(pieces.ok());
  ASSERT_GT(pieces->size(), 20u);  // 0.58 N s at <= 0.0216 N s per piece
  double mean_t = 0.0;
  for (std::size_t k = 0; k < pieces->size(); ++k) {
    mean_t += (*pieces)[k].t;
    if (k > 0) {
      // 46.5 s between impulses (docs/conventions.md Propulsion), centred (docs/algorithms/control.md#maneuver-buffering); measured 0 (2026-11)
      EXPECT_NEAR((*pieces)[k].t - (*pieces)[k - 1].t, 46.5, 1e-9);
    }
  }
  EXPECT_NEAR(mean_t / static_cast<double>(pieces->size()), kLargeImpulse.t, 1e-9);
}

// Acceptance criterion of the buffer: the net first-order ROE effect is preserved to 1e-6 m
// (before quantisation).
TEST(ManeuverBuffer, SplitPreservesTheNetRoeEffect) {
  const auto pieces = split_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(pieces.ok());
  const double t_ref = pieces->back().t;
  const astro::RelativeOrbitalElements planned = effect_of({kLargeImpulse}, t_ref);
  const astro::RelativeOrbitalElements split = effect_of(*pieces, t_ref);
  EXPECT_LT(kChief.a * (split - planned).cwiseAbs().maxCoeff(), 1e-6);  // [m]
}

// The equal split dv/K at the same times loses the de/di effect by the Dirichlet factor
// (docs/algorithms/control.md#maneuver-buffering: metres for this impulse); the buffer's pieces do
// not.
TEST(ManeuverBuffer, EqualSplitWouldMissTheTargetByMetres) {
  const auto pieces = split_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(pieces.ok());
  std::vector<Impulse> naive = *pieces;
  for (Impulse& p : naive) p.dv_rtn = kLargeImpulse.dv_rtn / static_cast<double>(naive.size());
  const double t_ref = pieces->back().t;
  const double error = kChief.a * (effect_of(naive, t_ref) -
                                   effect_of({kLargeImpulse}, t_ref)).norm();
  std::printf("equal split of (10, 50, 20) mm/s into %zu pieces: net effect off by %.2f m\n", naive.size(), error);
  EXPECT_GT(error, 1.0);
}

// Quantisation leaves only the last piece's rounding: <= half a quantum (2.8 um/s at 10.62 kg),
// i.e. a few millimetres of a*dROE (|a Gamma| ~ 2/n ~ 1800 s).
TEST(ManeuverBuffer, QuantisationResidualIsMillimetres) {
  const auto buffered = buffer_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(buffered.ok());
  const double residual = buffered->residual_roe_m.norm();
  std::printf("quantisation residual %.3f mm, dv total %.3f mm/s for a %.3f mm/s impulse\n", 1e3 * residual,
              1e3 * buffered->dv_total_mps, 1e3 * kLargeImpulse.dv_rtn.norm());
  EXPECT_LT(residual, 2.0 * 1800.0 * 0.5 * 6e-5 / kMass);  // [m]
}

// Independent of the linear model: propagate the deputy numerically (J2 only, DP8(7)) with the
// buffered pieces and with the single planned impulse; the mean ROE after the last piece differ
// only by what the first-order model leaves out (short-period and second-order terms).
TEST(ManeuverBuffer, PiecesMatchThePlannedImpulseInANumericalPropagation) {
  const auto buffered = buffer_impulse(kChief, kLargeImpulse, kMass);
  ASSERT_TRUE(buffered.ok());
  const double t_end = buffered->pieces.back().t + 60.0;
  const astro::RelativeOrbitalElements pieces =
      test::propagate_j2_numerically(kChief, astro::RelativeOrbitalElements::Zero(), buffered->pieces, t_end);
  const astro::RelativeOrbitalElements planned =
      test::propagate_j2_numerically(kChief, astro::RelativeOrbitalElements::Zero(), {kLargeImpulse}, t_end);
  const double difference = kChief.a * (pieces - planned).cwiseAbs().maxCoeff();
  std::printf("numerical J2 propagation: buffered vs planned impulse, max |a dROE| difference %.2f mm\n",
              1e3 * difference);
  // [m]: Gamma maps dv to MEAN ROE to first order; the osculating-to-mean Jacobian differs from
  // identity by O(J2) ~ 1e-3 and differently at the pieces' and the planned impulse's latitudes,
  // i.e. ~1e-3 of the ~100 m effect of this 55 mm/s maneuver (measured 45 mm).
  EXPECT_LT(difference, 0.1);
}

TEST(ManeuverBuffer, ASmallImpulseIsOnePiece) {
  const Impulse small{100.0, {0.0, 1e-3, 0.0}};  // 1 mm/s = 0.0106 N s
  const auto buffered = buffer_impulse(kChief, small, kMass);
  ASSERT_TRUE(buffered.ok());
  ASSERT_EQ(buffered->pieces.size(), 1u);
  EXPECT_EQ(buffered->pieces[0].t, 100.0);
}

// Below the minimum impulse (1e-3 N s = 94 um/s at 10.62 kg) nothing can be fired: the whole
// impulse becomes the residual.
TEST(ManeuverBuffer, AnImpulseBelowTheMinimumIsDroppedAndReported) {
  const Impulse tiny{100.0, {0.0, 5e-5, 0.0}};
  const auto buffered = buffer_impulse(kChief, tiny, kMass);
  ASSERT_TRUE(buffered.ok());
  EXPECT_TRUE(buffered->pieces.empty());
  EXPECT_GT(buffered->residual_roe_m.norm(), 0.05);  // 50 um/s * ~1800 s ~ 0.09 m
}

TEST(ManeuverBuffer, RejectsANonPositiveMass) {
  EXPECT_EQ(buffer_impulse(kChief, kLargeImpulse, 0.0).error().field, "mass");
}

TEST(ManeuverBuffer, RejectsANonFiniteDeltaV) {
  EXPECT_EQ(buffer_impulse(kChief, {0.0, {NAN, 0.0, 0.0}}, kMass).error().field, "maneuver.dv_rtn");
}

TEST(ManeuverBuffer, ReportsAnImpulseTooLargeForMaxPieces) {
  BufferSettings settings;
  settings.max_pieces = 5;
  EXPECT_EQ(buffer_impulse(kChief, kLargeImpulse, kMass, settings).error().field, "maneuver.dv_rtn");
}

}  // namespace
}  // namespace visors::control
