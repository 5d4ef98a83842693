#include "visors/nav/unimodular_transform.hpp"

#include <cassert>
#include <utility>

namespace visors::nav {

using Eigen::Index;

void UnimodularTransform::reset(Index n) {
  assert(n >= 0 && n <= kMaxAmbiguities);
  n_ = n;
  count_ = 0;
  folded_ = 0;
  has_base_ = false;
}

void UnimodularTransform::record(const Operation& op) {
  if (count_ == kTransformRecordCapacity) fold();
  record_[static_cast<std::size_t>(count_++)] = op;
}

void UnimodularTransform::exchange(Index i, Index j) {
  assert(i != j && i >= 0 && j >= 0 && i < n_ && j < n_);
  record({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), 0.0});
}

void UnimodularTransform::subtract(Index i, Index j, double mu) {
  assert(i != j && i >= 0 && j >= 0 && i < n_ && j < n_ && mu != 0.0);
  record({static_cast<std::int32_t>(i), static_cast<std::int32_t>(j), mu});
}

// Z = B E_1 ... E_c, each operation multiplying on the right: column j minus mu column i
// (E = I - mu e_i e_j') or an exchange.
void UnimodularTransform::replay(AmbiguityMatrix& Z) const {
  for (Index k = 0; k < count_; ++k) {
    const Operation& op = record_[static_cast<std::size_t>(k)];
    if (op.mu == 0.0) {
      Z.col(op.i).swap(Z.col(op.j));
    } else {
      Z.col(op.j) -= op.mu * Z.col(op.i);
    }
  }
}

// Z^-T = B^-T E_1^-T ... E_c^-T with E^-T = I + mu e_j e_i': column i plus mu column j.
void UnimodularTransform::replay_inverse_transpose(AmbiguityMatrix& Z_inv_t) const {
  for (Index k = 0; k < count_; ++k) {
    const Operation& op = record_[static_cast<std::size_t>(k)];
    if (op.mu == 0.0) {
      Z_inv_t.col(op.i).swap(Z_inv_t.col(op.j));
    } else {
      Z_inv_t.col(op.i) += op.mu * Z_inv_t.col(op.j);
    }
  }
}

void UnimodularTransform::fold() {
  if (!has_base_) {
    base_.setIdentity(n_, n_);
    base_inv_t_.setIdentity(n_, n_);
    has_base_ = true;
  }
  replay(base_);
  replay_inverse_transpose(base_inv_t_);
  folded_ += count_;
  count_ = 0;
}

// Z' V = E_c' ... E_1' B' V: B' first, then the operations in order; E' V changes only row j, by
// -mu times row i. Each operation depends on the previous ones through V, so the columns are
// transformed together: independent chains the processor overlaps.
void UnimodularTransform::apply_transpose(Eigen::Ref<Eigen::MatrixXd> V) const {
  assert(V.rows() == n_ && V.cols() <= kMaxCandidates);
  if (has_base_) {
    scratch_.resize(n_, V.cols());
    for (Index c = 0; c < V.cols(); ++c) {
      for (Index r = 0; r < n_; ++r) scratch_(r, c) = base_.col(r).head(n_).dot(V.col(c));
    }
    V = scratch_;
  }
  for (Index k = 0; k < count_; ++k) {
    const Operation& op = record_[static_cast<std::size_t>(k)];
    if (op.mu == 0.0) {
      V.row(op.i).swap(V.row(op.j));
    } else {
      for (Index c = 0; c < V.cols(); ++c) V(op.j, c) -= op.mu * V(op.i, c);
    }
  }
}

// Z^-T V = B^-T E_1^-T ... E_c^-T V: the operations in reverse order (row j plus mu row i), then B^-T.
void UnimodularTransform::apply_inverse_transpose(Eigen::Ref<Eigen::MatrixXd> V) const {
  assert(V.rows() == n_ && V.cols() <= kMaxCandidates);
  for (Index k = count_ - 1; k >= 0; --k) {
    const Operation& op = record_[static_cast<std::size_t>(k)];
    if (op.mu == 0.0) {
      V.row(op.i).swap(V.row(op.j));
    } else {
      for (Index c = 0; c < V.cols(); ++c) V(op.j, c) += op.mu * V(op.i, c);
    }
  }
  if (has_base_) {
    scratch_.resize(n_, V.cols());
    scratch_.setZero();
    for (Index c = 0; c < V.cols(); ++c) {
      for (Index k = 0; k < n_; ++k) scratch_.col(c) += V(k, c) * base_inv_t_.col(k).head(n_);
    }
    V = scratch_;
  }
}

void UnimodularTransform::matrix(AmbiguityMatrix& Z) const {
  if (has_base_) {
    Z = base_;
  } else {
    Z.setIdentity(n_, n_);
  }
  replay(Z);
}

void UnimodularTransform::inverse_transpose_matrix(AmbiguityMatrix& Z_inv_t) const {
  if (has_base_) {
    Z_inv_t = base_inv_t_;
  } else {
    Z_inv_t.setIdentity(n_, n_);
  }
  replay_inverse_transpose(Z_inv_t);
}

}  // namespace visors::nav
