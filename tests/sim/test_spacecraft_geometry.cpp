#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "visors/core/constants.hpp"
#include "visors/sim/spacecraft_geometry.hpp"

namespace {

using visors::sim::GeometrySettings;
using visors::sim::RandomStream;
using visors::sim::SpacecraftGeometry;

GeometrySettings zero_sigma() {
  GeometrySettings s;
  s.com_sigma_m = 0.0;
  s.payload_position_sigma_m = 0.0;
  s.payload_pointing_sigma_rad = 0.0;
  return s;
}

TEST(SpacecraftGeometry, DefaultSettingsAreValid) { EXPECT_TRUE(GeometrySettings{}.validate().ok()); }

TEST(SpacecraftGeometry, ValidateNamesTheField) {
  GeometrySettings s;
  s.com_sigma_m = -1.0;
  EXPECT_EQ(s.validate().error().field, "com_sigma_m");
}

// Default (project choice, docs/requirements.md#internal-geometry): payload point (0.15, 0, 0) m
// on the +X face, nominal centre of mass at the origin.
TEST(SpacecraftGeometry, NominalPayloadFromComIsTheDefault) {
  RandomStream rng(1, "osc.geometry");
  EXPECT_EQ(SpacecraftGeometry::draw({}, rng).payload_from_com_nominal_body_m(), Eigen::Vector3d(0.15, 0.0, 0.0));
}

// Zero sigmas reproduce the nominal values bit for bit.
TEST(SpacecraftGeometry, ZeroSigmaGivesNominalPayloadFromCom) {
  RandomStream rng(1, "osc.geometry");
  const SpacecraftGeometry g = SpacecraftGeometry::draw(zero_sigma(), rng);
  EXPECT_EQ(g.payload_from_com_body_m(), g.payload_from_com_nominal_body_m());
}

TEST(SpacecraftGeometry, ZeroSigmaGivesNominalAxis) {
  RandomStream rng(1, "osc.geometry");
  const SpacecraftGeometry g = SpacecraftGeometry::draw(zero_sigma(), rng);
  EXPECT_EQ(g.payload_axis_body(), g.payload_axis_nominal_body());
}

TEST(SpacecraftGeometry, TrueAxisIsUnit) {
  RandomStream rng(2, "osc.geometry");
  // round-off of a unit vector (ulp(1) 2.2e-16); measured 0 (2026-11)
  EXPECT_NEAR(SpacecraftGeometry::draw({}, rng).payload_axis_body().norm(), 1.0, 1e-15);
}

// Sample statistics over N = 20000 draws from one stream; references are the default sigmas
// (Guffanti et al., AAS 23-149, 2023, Table 1(a); the phase centre's: docs/truth-and-knowledge.md)
// with 5-standard-error bands (mean: sigma / sqrt(N); std: sigma / sqrt(2N)).
constexpr int kDraws = 20000;
struct Moments {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), std = Eigen::Vector3d::Zero();
};
enum class Quantity { kCom, kPayloadPoint, kAxis, kPhaseCentre };

Moments sample(Quantity quantity) {
  RandomStream rng(11, "stats.geometry");
  Eigen::Vector3d sum = Eigen::Vector3d::Zero(), sum2 = Eigen::Vector3d::Zero();
  for (int k = 0; k < kDraws; ++k) {
    const SpacecraftGeometry g = SpacecraftGeometry::draw({}, rng);
    Eigen::Vector3d x;
    switch (quantity) {
      case Quantity::kCom: x = g.com_body_m() - g.com_nominal_body_m(); break;
      case Quantity::kPayloadPoint: x = g.payload_body_m() - g.payload_nominal_body_m(); break;
      case Quantity::kAxis: x = g.payload_axis_body() - g.payload_axis_nominal_body(); break;
      case Quantity::kPhaseCentre: x = g.phase_center_error_body_m(); break;
    }
    sum += x;
    sum2 += x.cwiseProduct(x);
  }
  Moments m;
  m.mean = sum / kDraws;
  m.std = (sum2 / kDraws - m.mean.cwiseProduct(m.mean)).cwiseSqrt();
  return m;
}

TEST(SpacecraftGeometry, CentreOfMassErrorIsUnbiased) {
  EXPECT_LT(sample(Quantity::kCom).mean.cwiseAbs().maxCoeff(), 5.0 * 3e-3 / std::sqrt(kDraws));
}

TEST(SpacecraftGeometry, CentreOfMassErrorHas3mmPerAxis) {
  EXPECT_LT((sample(Quantity::kCom).std.array() - 3e-3).abs().maxCoeff(), 5.0 * 3e-3 / std::sqrt(2.0 * kDraws));
}

TEST(SpacecraftGeometry, PayloadPointErrorIsUnbiased) {
  EXPECT_LT(sample(Quantity::kPayloadPoint).mean.cwiseAbs().maxCoeff(), 5.0 * 0.5e-3 / std::sqrt(kDraws));
}

TEST(SpacecraftGeometry, PayloadPointErrorHasHalfMillimetrePerAxis) {
  EXPECT_LT((sample(Quantity::kPayloadPoint).std.array() - 0.5e-3).abs().maxCoeff(),
            5.0 * 0.5e-3 / std::sqrt(2.0 * kDraws));
}

// Tilts of the +X axis show as its Y and Z components (sin t ~ t to 4e-9 relative at 30 arcsec),
// each with 1-sigma 30 arcsec (per-axis tilt, header comment).
TEST(SpacecraftGeometry, PointingTiltHas30ArcsecPerAxis) {
  const double sigma = 30.0 * visors::core::kArcsecToRad;
  const Eigen::Vector3d s = sample(Quantity::kAxis).std;
  EXPECT_LT(std::max(std::abs(s.y() - sigma), std::abs(s.z() - sigma)), 5.0 * sigma / std::sqrt(2.0 * kDraws));
}

TEST(SpacecraftGeometry, PointingTiltIsUnbiased) {
  const double sigma = 30.0 * visors::core::kArcsecToRad;
  const Eigen::Vector3d m = sample(Quantity::kAxis).mean;
  EXPECT_LT(std::max(std::abs(m.y()), std::abs(m.z())), 5.0 * sigma / std::sqrt(kDraws));
}

// Determinism: same seed and name -> identical geometry.
TEST(SpacecraftGeometry, SameSeedGivesIdenticalGeometry) {
  RandomStream a(7, "dsc.geometry"), b(7, "dsc.geometry");
  const SpacecraftGeometry ga = SpacecraftGeometry::draw({}, a), gb = SpacecraftGeometry::draw({}, b);
  EXPECT_TRUE(ga.payload_from_com_body_m() == gb.payload_from_com_body_m() &&
              ga.payload_axis_body() == gb.payload_axis_body());
}

TEST(SpacecraftGeometry, DifferentNamesGiveDifferentGeometry) {
  RandomStream a(7, "dsc.geometry"), b(7, "osc.geometry");
  EXPECT_NE(SpacecraftGeometry::draw({}, a).com_body_m(), SpacecraftGeometry::draw({}, b).com_body_m());
}

// The centre-of-mass knowledge error (Guffanti et al., AAS 23-149, 2023, sec. 5, its sensitivity
// study): drawn after the eight other numbers, so the same stream with and without it differs by
// exactly a vector of the given length, and its direction is isotropic (mean direction ~0 within 5
// standard errors, 1/sqrt(3N) per axis for a unit vector).
Eigen::Vector3d knowledge_offset(std::uint64_t seed, double length) {
  GeometrySettings with;
  with.com_knowledge_error_m = length;
  RandomStream a(seed, "dsc.geometry"), b(seed, "dsc.geometry");
  return SpacecraftGeometry::draw(with, a).com_body_m() - SpacecraftGeometry::draw({}, b).com_body_m();
}

TEST(SpacecraftGeometry, KnowledgeErrorMovesTheCentreOfMassByItsLength) {
  EXPECT_NEAR(knowledge_offset(3, 0.01).norm(), 0.01, 1e-15);
}

TEST(SpacecraftGeometry, KnowledgeErrorLeavesTheOtherDrawsAsTheyWere) {
  GeometrySettings with;
  with.com_knowledge_error_m = 0.02;
  RandomStream a(4, "osc.geometry"), b(4, "osc.geometry");
  const SpacecraftGeometry g = SpacecraftGeometry::draw(with, a), h = SpacecraftGeometry::draw({}, b);
  EXPECT_EQ(g.payload_axis_body(), h.payload_axis_body());
}

TEST(SpacecraftGeometry, KnowledgeErrorDirectionIsIsotropic) {
  constexpr int n = 4000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int k = 0; k < n; ++k) sum += knowledge_offset(static_cast<std::uint64_t>(100 + k), 1.0);
  EXPECT_LT((sum / n).cwiseAbs().maxCoeff(), 5.0 / std::sqrt(3.0 * n));
}

// The phase centre's calibration error (GeometrySettings default 5 mm per axis): drawn last, so
// every earlier draw of the stream is what it was without it.
TEST(SpacecraftGeometry, PhaseCentreErrorIsUnbiased) {
  EXPECT_LT(sample(Quantity::kPhaseCentre).mean.cwiseAbs().maxCoeff(), 5.0 * 5e-3 / std::sqrt(kDraws));
}

TEST(SpacecraftGeometry, PhaseCentreErrorHas5mmPerAxis) {
  EXPECT_LT((sample(Quantity::kPhaseCentre).std.array() - 5e-3).abs().maxCoeff(), 5.0 * 5e-3 / std::sqrt(2.0 * kDraws));
}

TEST(SpacecraftGeometry, PhaseCentreErrorLeavesTheCentreOfMassAsItWas) {
  GeometrySettings without;
  without.phase_center_knowledge_sigma_m = 0.0;
  RandomStream a(4, "osc.geometry"), b(4, "osc.geometry");
  EXPECT_EQ(SpacecraftGeometry::draw({}, a).com_body_m(), SpacecraftGeometry::draw(without, b).com_body_m());
}

TEST(SpacecraftGeometry, ZeroPhaseCentreSigmaGivesNoError) {
  GeometrySettings without;
  without.phase_center_knowledge_sigma_m = 0.0;
  RandomStream rng(5, "dsc.geometry");
  EXPECT_EQ(SpacecraftGeometry::draw(without, rng).phase_center_error_body_m(), Eigen::Vector3d::Zero());
}

TEST(SpacecraftGeometry, NegativePhaseCentreSigmaIsNamed) {
  GeometrySettings s;
  s.phase_center_knowledge_sigma_m = -1e-3;
  EXPECT_EQ(s.validate().error().field, "phase_center_knowledge_sigma_m");
}

TEST(SpacecraftGeometry, NegativeKnowledgeErrorIsNamed) {
  GeometrySettings s;
  s.com_knowledge_error_m = -1e-3;
  EXPECT_EQ(s.validate().error().field, "com_knowledge_error_m");
}

}  // namespace
