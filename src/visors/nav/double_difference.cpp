#include "visors/nav/double_difference.hpp"

#include <algorithm>
#include <cassert>
#include <cstddef>

namespace visors::nav {

using Eigen::Index;

core::Result<DoubleDifferenceAmbiguities> DoubleDifferenceAmbiguities::create(Index max_states) {
  if (max_states < 1) return core::Error{"max_states", "must be >= 1"};
  return DoubleDifferenceAmbiguities(max_states);
}

DoubleDifferenceAmbiguities::DoubleDifferenceAmbiguities(Index max_states)
    : max_states_(max_states),
      G_(Eigen::MatrixXd::Zero(kMaxAmbiguities, max_states)),
      a_(Eigen::VectorXd::Zero(kMaxAmbiguities)),
      Q_(Eigen::MatrixXd::Zero(kMaxAmbiguities, kMaxAmbiguities)),
      PGt_(Eigen::MatrixXd::Zero(max_states, kMaxAmbiguities)) {}

bool DoubleDifferenceAmbiguities::reset(Index n_states) {
  size_ = 0;
  group_count_ = 0;
  const bool ok = n_states >= 1 && n_states <= max_states_;
  n_states_ = ok ? n_states : 0;
  return ok;
}

Index DoubleDifferenceAmbiguities::reference_of(Index row) const {
  assert(row >= 0 && row < size_);
  return reference_[static_cast<std::size_t>(row)];
}

Index DoubleDifferenceAmbiguities::state_of(Index row) const {
  assert(row >= 0 && row < size_);
  return state_[static_cast<std::size_t>(row)];
}

// A state already used by an earlier group, as a satellite or as a reference.
bool DoubleDifferenceAmbiguities::in_use(Index state) const {
  const auto rows = std::span(state_).first(static_cast<std::size_t>(size_));
  const auto references = std::span(groups_).first(static_cast<std::size_t>(group_count_));
  return std::find(rows.begin(), rows.end(), state) != rows.end() ||
         std::find(references.begin(), references.end(), state) != references.end();
}

bool DoubleDifferenceAmbiguities::group_is_valid(Index reference, std::span<const Index> others) const {
  const auto valid = [&](Index i) { return i >= 0 && i < n_states_ && !in_use(i); };
  if (!valid(reference)) return false;
  if (static_cast<Index>(others.size()) > kMaxAmbiguities - size_) return false;
  for (std::size_t r = 0; r < others.size(); ++r) {
    if (!valid(others[r]) || others[r] == reference) return false;
    if (std::find(others.begin(), others.begin() + static_cast<std::ptrdiff_t>(r), others[r]) !=
        others.begin() + static_cast<std::ptrdiff_t>(r)) {
      return false;  // repeats an earlier satellite of the group
    }
  }
  return true;
}

bool DoubleDifferenceAmbiguities::add_group(Index reference, std::span<const Index> others) {
  if (!group_is_valid(reference, others)) return false;
  if (others.empty()) return true;
  groups_[static_cast<std::size_t>(group_count_++)] = reference;
  for (const Index other : others) {
    const auto row = static_cast<std::size_t>(size_);
    reference_[row] = reference;
    state_[row] = other;
    G_.row(size_).head(n_states_).setZero();
    G_(size_, other) = 1.0;
    G_(size_, reference) = -1.0;
    ++size_;
  }
  return true;
}

// Column r of P G' is P e_i - P e_ref; row r of G (P G') picks rows i and ref of that product.
// Only the lower triangle of Q is computed and mirrored: the four-term sums of Q(r, c) and
// Q(c, r) round differently, and the integer least squares wants Q exactly symmetric (it checks
// the symmetry and then reads the lower triangle).
bool DoubleDifferenceAmbiguities::evaluate(const Eigen::Ref<const Eigen::VectorXd>& x,
                                           const Eigen::Ref<const Eigen::MatrixXd>& P) {
  const Index n = n_states_;
  if (x.size() != n || P.rows() != n || P.cols() != n) return false;
  for (Index r = 0; r < size_; ++r) {
    const Index i = state_of(r);
    const Index ref = reference_of(r);
    a_(r) = x(i) - x(ref);
    PGt_.col(r).head(n) = P.col(i) - P.col(ref);
  }
  for (Index c = 0; c < size_; ++c) {
    for (Index r = c; r < size_; ++r) {
      Q_(r, c) = PGt_(state_of(r), c) - PGt_(reference_of(r), c);
      Q_(c, r) = Q_(r, c);
    }
  }
  return true;
}

}  // namespace visors::nav
