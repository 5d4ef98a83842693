#pragma once
// The integer unimodular transformation Z of the LAMBDA reduction (z = Z' a, Q_z = Z' Q Z), kept
// as the sequence of its elementary column operations rather than as a matrix: exchanges of two
// columns and integer Gauss transformations Z(:,j) -= mu Z(:,i).
//
// Why: the reduction of a 24-ambiguity problem does some 700-3,000 such operations. Applied to
// an explicit n x n Z and to its inverse each costs two length-n updates, while what every
// resolution needs is only Z' a (once) and Z^-T z for m candidates: O(1) per operation and vector
// here. The matrices are
// formed on request (matrix(), inverse_transpose_matrix()), by the callers that need them: the
// fixed-solution constraints of an accepted fix, tools and tests.
//
// Bounded memory: the record holds kTransformRecordCapacity operations; when it is full they are
// folded into explicit base matrices B and B^-T (Z = B E_1 ... E_c) and the record starts again,
// so any number of operations is represented (random condition-1e6 problems of 64 ambiguities
// take ~50,000).
//
// Exact: mu and the vectors transformed hold integers (|values| < 2^53) when the input is integer,
// and every operation is an integer combination, so Z' z and Z^-T z of integer z are exact.

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "visors/nav/ambiguity_capacity.hpp"

namespace visors::nav {

/// Operations recorded before they are folded into the base matrices: above the ~1,200 of a
/// 24-ambiguity dual-frequency problem and the ~3,500 of a random condition-1e6 one
/// (bench/bench_ambiguity.cpp), so neither folds.
inline constexpr int kTransformRecordCapacity = 4096;

class UnimodularTransform {
 public:
  /// Identity of size n (n <= kMaxAmbiguities).
  void reset(Eigen::Index n);

  [[nodiscard]] Eigen::Index n() const { return n_; }
  /// Operations applied since reset (folded ones included).
  [[nodiscard]] long operations() const { return folded_ + count_; }

  /// Z(:,i) <-> Z(:,j), i != j.
  void exchange(Eigen::Index i, Eigen::Index j);
  /// Z(:,j) -= mu Z(:,i), mu a non-zero integer, i != j.
  void subtract(Eigen::Index i, Eigen::Index j, double mu);

  /// V <- Z' V (V: n rows, at most kMaxCandidates columns, transformed in one pass).
  void apply_transpose(Eigen::Ref<Eigen::MatrixXd> V) const;
  /// V <- Z^-T V (V: n rows, at most kMaxCandidates columns): Z' (Z^-T V) = V.
  void apply_inverse_transpose(Eigen::Ref<Eigen::MatrixXd> V) const;
  /// Z explicitly (n x n).
  void matrix(AmbiguityMatrix& Z) const;
  /// Z^-T explicitly (n x n).
  void inverse_transpose_matrix(AmbiguityMatrix& Z_inv_t) const;

 private:
  struct Operation {
    std::int32_t i;
    std::int32_t j;
    double mu;  // 0: exchange of columns i and j
  };
  void record(const Operation& op);
  void fold();
  void replay(AmbiguityMatrix& Z) const;
  void replay_inverse_transpose(AmbiguityMatrix& Z_inv_t) const;

  std::array<Operation, kTransformRecordCapacity> record_{};
  Eigen::Index count_ = 0;   // operations in record_
  long folded_ = 0;          // operations folded into the base
  Eigen::Index n_ = 0;
  bool has_base_ = false;
  AmbiguityMatrix base_;        // B: Z = B E_1 ... E_c
  AmbiguityMatrix base_inv_t_;  // B^-T
  mutable CandidateMatrix scratch_;
};

}  // namespace visors::nav
