// Cone algebra and Nesterov-Todd scaling: defining identities checked numerically.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "visors/optim/cone.hpp"

namespace {

using visors::optim::ConeProduct;
using visors::optim::NtScaling;

// K = R+^2 x Q^3 x Q^1; s and z interior.
const ConeProduct kCone(2, {3, 1});
const std::vector<double> kS{0.5, 2.0, 3.0, 1.0, -1.5, 0.7};
const std::vector<double> kZ{1.5, 0.1, 1.2, 0.3, 0.8, 2.0};

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::abs(a[i] - b[i]));
  return d;
}

// Defining property of the NT scaling (Vandenberghe 2010 sec. 4): W z = W^{-1} s = lambda.
TEST(NtScaling, MapsZAndSToTheSamePoint) {
  NtScaling nt(kCone);
  std::vector<double> lambda(6), winv_s(6);
  ASSERT_TRUE(nt.update(kS.data(), kZ.data(), lambda.data()));
  nt.apply_inverse(kS.data(), winv_s.data());
  // round-off of the NT scaling (entries ~1); measured 2.2e-16 (2026-11), bound 1e-14
  EXPECT_LT(max_abs_diff(lambda, winv_s), 1e-14);
}

TEST(NtScaling, InverseIsTheInverse) {
  NtScaling nt(kCone);
  std::vector<double> lambda(6), u{0.3, -1.0, 2.0, 0.5, -0.25, 4.0}, wu(6), back(6);
  ASSERT_TRUE(nt.update(kS.data(), kZ.data(), lambda.data()));
  nt.apply(u.data(), wu.data());
  nt.apply_inverse(wu.data(), back.data());
  // round-off; measured 4.4e-16 (2026-11), bound 1e-14
  EXPECT_LT(max_abs_diff(u, back), 1e-14);
}

// W^2 = eta^2 (2 w w' - J) (from w'Jw = 1) equals applying W twice; likewise W^-2.
TEST(NtScaling, SquareEqualsTwoApplications) {
  NtScaling nt(kCone);
  std::vector<double> lambda(6), u{0.3, -1.0, 2.0, 0.5, -0.25, 4.0}, once(6), twice(6), square(6);
  ASSERT_TRUE(nt.update(kS.data(), kZ.data(), lambda.data()));
  nt.apply(u.data(), once.data());
  nt.apply(once.data(), twice.data());
  nt.apply_square(u.data(), square.data());
  // round-off; measured 1.8e-15 (2026-11), bound 1e-13
  EXPECT_LT(max_abs_diff(twice, square), 1e-13);
}

TEST(NtScaling, InverseSquareEqualsTwoInverseApplications) {
  NtScaling nt(kCone);
  std::vector<double> lambda(6), u{0.3, -1.0, 2.0, 0.5, -0.25, 4.0}, once(6), twice(6), square(6);
  ASSERT_TRUE(nt.update(kS.data(), kZ.data(), lambda.data()));
  nt.apply_inverse(u.data(), once.data());
  nt.apply_inverse(once.data(), twice.data());
  for (int b = 0; b < nt.blocks(); ++b) {
    const int r0 = nt.block_start(b);
    nt.apply_inverse_square_block(b, u.data() + r0, square.data() + r0);
  }
  // loose: measured 2.2e-16 (2026-11), bound 1e-13 ~450x above round-off
  EXPECT_LT(max_abs_diff(twice, square), 1e-13);
}

// The matrix form applies W to every column of a row-major block like the vector form.
TEST(NtScaling, BlockRowsEqualColumnByColumnApplication) {
  NtScaling nt(kCone);
  std::vector<double> lambda(6);
  ASSERT_TRUE(nt.update(kS.data(), kZ.data(), lambda.data()));
  constexpr int kCols = 3;
  std::vector<double> in(6 * kCols), rows(6 * kCols), columns(6 * kCols);
  for (std::size_t i = 0; i < in.size(); ++i) in[i] = std::sin(1.0 + static_cast<double>(i));
  for (int b = 0; b < nt.blocks(); ++b) {
    const int r0 = nt.block_start(b);
    nt.apply_block_rows(b, in.data() + r0 * kCols, rows.data() + r0 * kCols, kCols);
    for (int c = 0; c < kCols; ++c) nt.apply_block(b, in.data() + r0 * kCols + c, columns.data() + r0 * kCols + c, kCols);
  }
  // round-off; measured 0 (identical arithmetic) (2026-11)
  EXPECT_LT(max_abs_diff(rows, columns), 1e-14);
}

TEST(NtScaling, RejectsBoundaryPoint) {
  NtScaling nt(kCone);
  std::vector<double> s = kS, lambda(6);
  s[2] = 1.0;  // SOC block (1, 1, -1.5) has 1 < ||(1, -1.5)||: outside
  EXPECT_FALSE(nt.update(s.data(), kZ.data(), lambda.data()));
}

// x = u \ r solves u o x = r.
TEST(ConeProduct, DivideInvertsProduct) {
  std::vector<double> r{1.0, -2.0, 0.5, 0.25, 3.0, -1.0}, x(6), back(6);
  kCone.divide(kS.data(), r.data(), x.data());
  kCone.product(kS.data(), x.data(), back.data());
  // round-off; measured 0 (2026-11)
  EXPECT_LT(max_abs_diff(r, back), 1e-13);
}

// From x = (1, 0, 0) (the SOC identity) along d = (0, 1, 0) the boundary x0 = ||x1|| is at a = 1;
// the orthant step from 0.5 along -1 is 0.5.
TEST(ConeProduct, MaxStepToBoundary) {
  const ConeProduct soc(0, {3});
  const std::vector<double> x{1.0, 0.0, 0.0}, d{0.0, 1.0, 0.0};
  // round-off (ulp(1) 2.2e-16); measured 0 (2026-11)
  EXPECT_NEAR(soc.max_step(x.data(), d.data(), 10.0), 1.0, 1e-15);
  const ConeProduct orthant(1, {});
  const double xo = 0.5, dn = -1.0;
  EXPECT_NEAR(orthant.max_step(&xo, &dn, 10.0), 0.5, 1e-15);
}

TEST(ConeProduct, DegreeCountsConesOnce) { EXPECT_EQ(kCone.degree(), 4); }

}  // namespace
