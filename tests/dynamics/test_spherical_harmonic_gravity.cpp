// Spherical-harmonic gravity against published vectors (Montenbruck & Gill / JGM-3; worked examples
// in docs/algorithms/dynamics.md#gravity-worked-examples),
// an independent implementation (GeographicLib::SphericalHarmonic, Clenshaw summation) with the
// same coefficients, closed forms and the gradient's own identities.
#include <gtest/gtest.h>


#include <algorithm>
#include <cstdio>
#include <numbers>
#include <optional>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "visors/core/files/data_path.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"
#include "support/geographiclib_gravity.hpp"

namespace {
using visors::dynamics::GravityField;
using visors::dynamics::SphericalHarmonicGravity;

// Reads a gravity file of the data search path; empty when absent (the caller skips).
std::optional<GravityField> load_field(const std::string& relative, int degree = -1) {
  const auto path = visors::core::files::find_data_file(relative);
  if (!path) return std::nullopt;
  auto field = visors::dynamics::files::read_icgem(*path, degree);
  if (!field.ok()) {
    ADD_FAILURE() << field.error().describe();
    return std::nullopt;
  }
  return std::move(field).value();
}
#define REQUIRE_FIELD(var, relative, degree)                                                 \
  const std::optional<GravityField> var = load_field(relative, degree);                     \
  if (!var) FAIL() << relative << " not found in the data search path (data/SOURCES.md)"

SphericalHarmonicGravity make(const GravityField& field, int degree, int order) {
  auto g = SphericalHarmonicGravity::create(field, degree, order);
  EXPECT_TRUE(g.ok()) << g.error().describe();
  return std::move(g).value();
}

// Random points, altitude log-uniform in 300 km .. 40,000 km above R, direction uniform.
std::vector<Eigen::Vector3d> random_points(int count, double radius, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) {
    const double altitude = 300e3 * std::pow(40000.0 / 300.0, unit(rng));
    const double sin_lat = 2.0 * unit(rng) - 1.0;
    const double lon = 2.0 * std::numbers::pi * unit(rng);
    const double cos_lat = std::sqrt(1.0 - sin_lat * sin_lat);
    points.emplace_back((radius + altitude) * Eigen::Vector3d(cos_lat * std::cos(lon), cos_lat * std::sin(lon), sin_lat));
  }
  return points;
}

const Eigen::Vector3d kMgPosition(6525.919e3, 1710.416e3, 2508.886e3);  // M&G test point, body-fixed [m]

struct ReferenceVector {
  int degree;
  Eigen::Vector3d a;  // [m/s^2]
};

// Montenbruck & Gill reference vectors with JGM-3, E = I (the values of M&G's accompanying
// software as tabulated in brahe's gravity.rs test_accel_gravity_jgm3_validation). Tolerance
// 1e-7 m/s^2 as published to ~1e-8.
TEST(SphericalHarmonicGravity, Jgm3MontenbruckGillVectors) {
  REQUIRE_FIELD(field, "gravity/JGM3.gfc", 20);
  const ReferenceVector references[] = {
      {2, {-6.97922756436, -1.8292810538, -2.69001658552}},
      {3, {-6.97926211185, -1.82929165145, -2.68998602761}},
      {4, {-6.97931189287, -1.82931487069, -2.6899914012}},
      {10, {-6.97924447943, -1.82928331386, -2.68997524437}},
      {20, {-6.979261862, -1.82928315091, -2.68999053339}},
  };
  double worst = 0.0;
  for (const ReferenceVector& ref : references) {
    SphericalHarmonicGravity g = make(*field, ref.degree, ref.degree);
    worst = std::max(worst, (g.acceleration(kMgPosition) - ref.a).cwiseAbs().maxCoeff());
  }
  RecordProperty("max_abs_difference", testing::PrintToString(worst));
  EXPECT_LT(worst, 1e-7);
}

// GGM05S 60x60 at the M&G point, an independent evaluation (central differences of the potential,
// column-wise Legendre functions): docs/algorithms/dynamics.md#gravity-worked-examples.
TEST(SphericalHarmonicGravity, Ggm05s60WorkedVector) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d70.gfc", 60);
  SphericalHarmonicGravity g = make(*field, 60, 60);
  const Eigen::Vector3d ref(-6.9792607656, -1.8292848885, -2.6899854388);
  // loose: measured 3.6e-11 m/s^2 (2026-11), bound 1e-7 ~3000x above (the M&G tolerance reused)
  EXPECT_LT((g.acceleration(kMgPosition) - ref).cwiseAbs().maxCoeff(), 1e-7);
}

// GGM01S 20x20 at the M&G point, evaluated as above (docs/algorithms/dynamics.md#gravity-worked-examples).
TEST(SphericalHarmonicGravity, Ggm01s20WorkedVector) {
  REQUIRE_FIELD(field, "gravity/GGM01S.gfc", 20);
  SphericalHarmonicGravity g = make(*field, 20, 20);
  const Eigen::Vector3d ref(-6.9792625603, -1.8292834269, -2.6899896973);
  // loose: measured 4.8e-11 m/s^2 (2026-11), bound 1e-7 ~2000x above (the M&G tolerance reused)
  EXPECT_LT((g.acceleration(kMgPosition) - ref).cwiseAbs().maxCoeff(), 1e-7);
}

// Independent oracle: GeographicLib (Clenshaw summation) with the same GGM05S coefficients, 250
// random points per degree, degrees 2..90 and one order-truncated case.
TEST(SphericalHarmonicGravity, MatchesGeographicLibAcceleration) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  double worst_a = 0.0;
  double worst_u = 0.0;
  for (const auto& [degree, order] : {std::pair{2, 2}, {4, 4}, {8, 8}, {20, 20}, {45, 45}, {60, 60}, {60, 30},
                                     {90, 90}, {90, 0}}) {
    SphericalHarmonicGravity g = make(*field, degree, order);
    const visors::test::GeographicLibGravity oracle(*field, degree, order);
    for (const Eigen::Vector3d& r : random_points(250, field->radius, 20241001 + static_cast<unsigned>(degree))) {
      Eigen::Vector3d a_ref;
      double u_ref = 0.0;
      oracle.evaluate(r, &a_ref, &u_ref);
      const auto both = g.acceleration_and_potential(r);
      worst_a = std::max(worst_a, (g.acceleration(r) - a_ref).norm() / a_ref.norm());
      worst_a = std::max(worst_a, (both.a_itrf - a_ref).norm() / a_ref.norm());
      worst_u = std::max(worst_u, std::abs(g.potential(r) - u_ref) / std::abs(u_ref));
      worst_u = std::max(worst_u, std::abs(both.potential - u_ref) / std::abs(u_ref));
    }
  }
  RecordProperty("max_relative_difference_acceleration", testing::PrintToString(worst_a));
  RecordProperty("max_relative_difference_potential", testing::PrintToString(worst_u));
  std::printf("[ GeographicLib ] max relative difference: acceleration %.3e, potential %.3e\n", worst_a, worst_u);
  // loose: measured 1.7e-15 / 1.5e-15 (2026-11), bounds 1e-12 ~600x above round-off
  EXPECT_LT(worst_a, 1e-12);
  EXPECT_LT(worst_u, 1e-12);
}

// The non-central part alone, relative to its own size (a stricter view than the full vector).
TEST(SphericalHarmonicGravity, MatchesGeographicLibNonCentralPart) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  SphericalHarmonicGravity g = make(*field, 90, 90);
  const visors::test::GeographicLibGravity oracle(*field, 90, 90);
  double worst = 0.0;
  for (const Eigen::Vector3d& r : random_points(200, field->radius, 7)) {
    Eigen::Vector3d a_ref;
    double u_ref = 0.0;
    oracle.evaluate(r, &a_ref, &u_ref);
    const Eigen::Vector3d central = -field->gm * r / std::pow(r.norm(), 3);
    worst = std::max(worst, (g.acceleration(r) - a_ref).norm() / (a_ref - central).norm());
  }
  RecordProperty("max_relative_difference_noncentral", testing::PrintToString(worst));
  // measured regression bound: 2.0e-11 (2026-11); bound 1e-9
  EXPECT_LT(worst, 1e-9);
}

// Central differences of the acceleration, h = 10 m (truncation ~1e-14 s^-2, round-off ~1e-16).
Eigen::Matrix3d finite_difference_gradient(SphericalHarmonicGravity& g, const Eigen::Vector3d& r) {
  const double h = 10.0;
  Eigen::Matrix3d fd;
  for (int l = 0; l < 3; ++l) {
    const Eigen::Vector3d step = h * Eigen::Vector3d::Unit(l);
    fd.col(l) = (g.acceleration(r + step) - g.acceleration(r - step)) / (2.0 * h);
  }
  return fd;
}

TEST(SphericalHarmonicGravity, GradientMatchesFiniteDifferences) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  double worst = 0.0;
  for (const auto& [degree, order] : {std::pair{2, 2}, {20, 20}, {60, 30}, {90, 90}}) {
    SphericalHarmonicGravity g = make(*field, degree, order);
    for (const Eigen::Vector3d& r : random_points(30, field->radius, 99)) {
      const Eigen::Matrix3d grad = g.gradient(r);
      worst = std::max(worst, (grad - finite_difference_gradient(g, r)).cwiseAbs().maxCoeff() /
                                  grad.cwiseAbs().maxCoeff());
    }
  }
  RecordProperty("max_relative_difference", testing::PrintToString(worst));
  // measured regression bound: 1.65e-9 (2026-11); bound 1e-7 (60x)
  EXPECT_LT(worst, 1e-7);
}

// ∂a_i/∂x_l = ∂²U/∂x_i∂x_l: the nine entries are computed independently, so symmetry is a check.
TEST(SphericalHarmonicGravity, GradientIsSymmetric) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  SphericalHarmonicGravity g = make(*field, 90, 90);
  double worst = 0.0;
  for (const Eigen::Vector3d& r : random_points(50, field->radius, 5)) {
    const Eigen::Matrix3d grad = g.gradient(r);
    worst = std::max(worst, (grad - grad.transpose()).cwiseAbs().maxCoeff() / grad.cwiseAbs().maxCoeff());
  }
  // loose: measured 1.1e-15 (2026-11), bound 1e-12 ~900x above round-off
  EXPECT_LT(worst, 1e-12);
}

// Laplace: trace of the gradient = ∇²U = 0 outside the masses.
TEST(SphericalHarmonicGravity, GradientTraceVanishes) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  SphericalHarmonicGravity g = make(*field, 90, 90);
  double worst = 0.0;
  for (const Eigen::Vector3d& r : random_points(50, field->radius, 6)) {
    const Eigen::Matrix3d grad = g.gradient(r);
    worst = std::max(worst, std::abs(grad.trace()) / grad.cwiseAbs().maxCoeff());
  }
  // loose: measured 1.3e-15 (2026-11), bound 1e-12 ~800x above round-off
  EXPECT_LT(worst, 1e-12);
}

// Only C̄00 = 1 and C̄20: textbook J2 acceleration with J2 = -sqrt(5) C̄20
// (e.g. Vallado, "Fundamentals of Astrodynamics", 4th ed., eq. 8-30).
TEST(SphericalHarmonicGravity, J2OnlyMatchesClosedForm) {
  GravityField field = visors::dynamics::embedded_gravity_field();
  std::fill(field.c_bar.begin(), field.c_bar.end(), 0.0);
  std::fill(field.s_bar.begin(), field.s_bar.end(), 0.0);
  field.c_bar[0] = 1.0;
  field.c_bar[GravityField::index(2, 0)] = -4.841694573200e-4;
  SphericalHarmonicGravity g = make(field, 2, 2);
  const double j2 = -std::sqrt(5.0) * field.c(2, 0);
  double worst = 0.0;
  for (const Eigen::Vector3d& r : random_points(100, field.radius, 3)) {
    const double rn = r.norm();
    const double z2 = r.z() * r.z() / (rn * rn);
    const double k = -1.5 * j2 * field.gm * field.radius * field.radius / std::pow(rn, 5);
    const Eigen::Vector3d ref = -field.gm * r / (rn * rn * rn) +
                                k * Eigen::Vector3d(r.x() * (1.0 - 5.0 * z2), r.y() * (1.0 - 5.0 * z2),
                                                    r.z() * (3.0 - 5.0 * z2));
    worst = std::max(worst, (g.acceleration(r) - ref).norm() / ref.norm());
  }
  // round-off; measured 6.9e-16 (2026-11)
  EXPECT_LT(worst, 1e-14);
}

// The Cartesian V/W recursion has no pole singularity (Cunningham 1970). At (0, 0, ±7000 km) the
// results are finite, and a 1 mm step off the axis changes the acceleration by the gradient times
// the step (to round-off, 1e-14 m/s^2: a ~ 8 m/s^2 with 1e-16 relative rounding).
TEST(SphericalHarmonicGravity, PolesFiniteAndContinuous) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 90);
  SphericalHarmonicGravity g = make(*field, 90, 90);
  double worst = 0.0;
  bool finite = true;
  for (const double z : {7000e3, -7000e3}) {
    const Eigen::Vector3d pole(0.0, 0.0, z);
    const Eigen::Vector3d step(1e-3, 0.0, 0.0);
    const Eigen::Vector3d a = g.acceleration(pole);
    const Eigen::Matrix3d grad = g.gradient(pole);
    finite = finite && a.allFinite() && std::isfinite(g.potential(pole)) && grad.allFinite();
    const Eigen::Vector3d predicted = a + grad * step;
    worst = std::max(worst, (g.acceleration(pole + step) - predicted).norm());
  }
  EXPECT_TRUE(finite);
  EXPECT_LT(worst, 1e-14);
}

// The embedded 8x8 field gives the same acceleration as the file truncated to 8x8.
TEST(SphericalHarmonicGravity, EmbeddedFieldMatchesFileAtDegree8) {
  REQUIRE_FIELD(field, "gravity/GGM05S_d90.gfc", 8);
  SphericalHarmonicGravity from_file = make(*field, 8, 8);
  SphericalHarmonicGravity embedded = make(visors::dynamics::embedded_gravity_field(), 8, 8);
  double worst = 0.0;
  for (const Eigen::Vector3d& r : random_points(20, field->radius, 11)) {
    worst = std::max(worst, (from_file.acceleration(r) - embedded.acceleration(r)).norm());
  }
  EXPECT_EQ(worst, 0.0);
}

// The workspace carries no state between calls: after a NaN input, the next evaluation equals
// that of a fresh instance bit for bit.
TEST(SphericalHarmonicGravity, NoStateLeaksBetweenCalls) {
  const GravityField field = visors::dynamics::embedded_gravity_field();
  SphericalHarmonicGravity used = make(field, 8, 8);
  SphericalHarmonicGravity fresh = make(field, 8, 8);
  const Eigen::Vector3d r(6878e3, 1200e3, -2500e3);
  (void)used.acceleration_and_potential(Eigen::Vector3d(std::nan(""), 1.0, 1.0));
  (void)used.gradient(Eigen::Vector3d(std::nan(""), 1.0, 1.0));
  EXPECT_EQ(used.acceleration(r), fresh.acceleration(r));
}

TEST(SphericalHarmonicGravity, CreateRejectsDegreeAboveField) {
  const auto g = SphericalHarmonicGravity::create(visors::dynamics::embedded_gravity_field(), 9, 9);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().field, "degree");
}

TEST(SphericalHarmonicGravity, CreateRejectsOrderAboveDegree) {
  const auto g = SphericalHarmonicGravity::create(visors::dynamics::embedded_gravity_field(), 4, 5);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().field, "order");
}

TEST(SphericalHarmonicGravity, CreateRejectsNegativeOrder) {
  const auto g = SphericalHarmonicGravity::create(visors::dynamics::embedded_gravity_field(), 4, -1);
  ASSERT_FALSE(g.ok());
  EXPECT_EQ(g.error().field, "order");
}

// Degree 0 is the point mass: -GM r / r^3 exactly (up to rounding).
TEST(SphericalHarmonicGravity, DegreeZeroIsPointMass) {
  const GravityField field = visors::dynamics::embedded_gravity_field();
  SphericalHarmonicGravity g = make(field, 0, 0);
  const Eigen::Vector3d r(7000e3, -1200e3, 3000e3);
  const Eigen::Vector3d ref = -field.gm * r / std::pow(r.norm(), 3);
  EXPECT_LT((g.acceleration(r) - ref).norm() / ref.norm(), 1e-15);
}

}  // namespace
