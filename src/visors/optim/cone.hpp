#pragma once
// The cone K = R+^l x Q^{q1} x ... x Q^{qN} of the conic solver and its Jordan algebra
// (Vandenberghe 2010, "The CVXOPT linear and quadratic cone program solvers", sec. 2-4).
// A second-order cone Q^q = {(u0, u1) : u0 >= ||u1||_2}, u1 of dimension q - 1.
// Vectors are laid out orthant first, then each second-order cone in order. Everything here
// works on raw pointers into preallocated storage and allocates nothing.

#include <vector>

namespace visors::optim {

class ConeProduct {
 public:
  ConeProduct() = default;
  /// l orthant rows followed by second-order cones of the given dimensions (each >= 1).
  ConeProduct(int l, std::vector<int> q);

  [[nodiscard]] int rows() const { return rows_; }
  [[nodiscard]] int orthant() const { return l_; }
  [[nodiscard]] int soc_count() const { return static_cast<int>(q_.size()); }
  [[nodiscard]] int soc_dim(int k) const { return q_[k]; }
  [[nodiscard]] int soc_start(int k) const { return start_[k]; }
  /// Degree nu = l + number of second-order cones (the barrier parameter).
  [[nodiscard]] int degree() const { return l_ + soc_count(); }

  /// out = u o v (Jordan product: orthant elementwise, SOC (u'v, u0 v1 + v0 u1)).
  void product(const double* u, const double* v, double* out) const;
  /// out = u \ r, the solution of u o out = r (u in the interior of K).
  void divide(const double* u, const double* r, double* out) const;
  /// x += a e, e the identity (1 on the orthant, (1, 0, ..., 0) per SOC).
  void add_identity(double* x, double a) const;
  /// min over blocks of x_i (orthant) or x0 - ||x1|| (SOC): > 0 iff x is in the interior.
  [[nodiscard]] double interior_margin(const double* x) const;
  /// Largest a (capped at `cap`) with x + a d in K, for x in the interior of K.
  [[nodiscard]] double max_step(const double* x, const double* d, double cap) const;

 private:
  int l_ = 0;
  int rows_ = 0;
  std::vector<int> q_;
  std::vector<int> start_;
};

/// Nesterov-Todd scaling W of a pair (s, z) in int K: the symmetric positive definite W, mapping
/// K onto itself, with W z = W^{-1} s = lambda. Orthant: W = diag(sqrt(s/z)). SOC (Domahidi, Chu &
/// Boyd 2013, ECOS, sec. 3.2, following Vandenberghe 2010 sec. 4.3):
///   eta = (s'Js / z'Jz)^(1/4), sb = s/sqrt(s'Js), zb = z/sqrt(z'Jz), gamma = sqrt((1+sb'zb)/2),
///   w = (sb + J zb)/(2 gamma),  W = eta [w0 w1'; w1 I + w1 w1'/(1+w0)],
///   W^{-1} = (1/eta) [w0 -w1'; -w1 I + w1 w1'/(1+w0)],  J = diag(1, -1, ..., -1).
class NtScaling {
 public:
  NtScaling() = default;
  explicit NtScaling(const ConeProduct& cone);

  /// Computes W from (s, z) and writes lambda = W z. Returns false if s or z is not interior.
  bool update(const double* s, const double* z, double* lambda);
  /// Identity scaling (W = I).
  void set_identity();
  /// out = W in / out = W^{-1} in, over the whole cone (in != out).
  void apply(const double* in, double* out) const;
  void apply_inverse(const double* in, double* out) const;
  /// out = W in on the rows [start, start + dim) of one block; `in` and `out` point at the
  /// block's first row and step by `stride` (in != out).
  void apply_block(int block, const double* in, double* out, int stride) const;
  /// out = W^{-1} in on the rows [start, start + dim) of one block; `in` and `out` point at the
  /// block's first row and step by `stride` (to scale matrix columns in place of vectors).
  void apply_inverse_block(int block, const double* in, double* out, int stride) const;
  /// out = W in on one block for a matrix: `in` and `out` are the block's dim x cols rows of
  /// row-major matrices (cols consecutive values per row; in != out).
  void apply_block_rows(int block, const double* in, double* out, int cols) const;
  /// out = W^2 in / out = W^-2 in on one block (stride 1, in != out). For a SOC, from w'Jw = 1:
  /// W^2 = eta^2 (2 w w' - J) and W^-2 = eta^-2 (2 (Jw)(Jw)' - J): one dot product and one
  /// update instead of two applications of W.
  void apply_square_block(int block, const double* in, double* out) const;
  void apply_inverse_square_block(int block, const double* in, double* out) const;
  /// out = W^2 in over the whole cone (in != out).
  void apply_square(const double* in, double* out) const;
  /// Blocks: the l orthant rows one by one, then the second-order cones.
  [[nodiscard]] int blocks() const { return cone_.orthant() + cone_.soc_count(); }
  [[nodiscard]] int block_start(int block) const {
    return block < cone_.orthant() ? block : cone_.soc_start(block - cone_.orthant());
  }
  [[nodiscard]] int block_dim(int block) const {
    return block < cone_.orthant() ? 1 : cone_.soc_dim(block - cone_.orthant());
  }

 private:
  ConeProduct cone_;  // a copy: the scaling stays valid when its owner moves
  std::vector<double> w_;    // orthant: sqrt(s/z); SOC: the vector w of each cone
  std::vector<double> eta_;  // one per SOC
  // Reciprocals computed once per update(), so the many applications per iteration multiply:
  // orthant 1/w_i; per SOC 1/eta and 1/(1 + w0).
  std::vector<double> w_inv_;
  std::vector<double> eta_inv_;
  std::vector<double> w0_inv_;
};

}  // namespace visors::optim
