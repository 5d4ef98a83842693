#pragma once
// Single-difference (SD) to double-difference (DD) ambiguities with a reference satellite
// (docs/algorithms/ambiguity-resolution.md#single-to-double-differences). A filter holds SD
// (receiver-receiver) ambiguity states [cycles] at some indices of its state vector x (n_x states,
// covariance P). For each frequency one satellite is the reference; every other satellite r of that
// frequency gives one DD ambiguity
//   a_r = x(i_r) - x(ref) = G_r x,  G_r = e_{i_r}' - e_ref'
// (+1 for the satellite, -1 for the reference; RTKLIB's ddmat has the opposite sign). The
// receiver phase offset common to the SDs of one frequency cancels, so the DDs are integers.
// Outputs:
//   a = G x [cycles],  Q = G P G' [cycles^2],  PGt = P G' [state unit x cycles]
// PGt is the cross-covariance a conditional update of the whole state needs
// (docs/algorithms/ambiguity-resolution.md#fixed-solution-update).
//
// Holding SD states rather than DD states means a change of reference needs no state remapping:
// only G changes. G has two non-zeros per row, so a, Q and PGt are computed by
// index in O(n_x k + k^2), not as dense products; the dense G is kept for the caller (and for the
// fixed constraints C = Z_k' G, fixed_solution.hpp).
//
// Fixed capacity: n_x <= max_states (chosen at create()), k <= kMaxAmbiguities. All storage is
// made by create(); reset, add_group and evaluate allocate nothing.

#include <array>
#include <span>

#include <Eigen/Core>

#include "visors/core/result.hpp"
#include "visors/nav/ambiguity_capacity.hpp"

namespace visors::nav {

class DoubleDifferenceAmbiguities {
 public:
  /// Capacity: filter states up to max_states (>= 1), DD ambiguities up to kMaxAmbiguities.
  /// The error names the field.
  static core::Result<DoubleDifferenceAmbiguities> create(Eigen::Index max_states);

  /// Starts a new, empty set for a filter of n_states states (1..max_states); false (and an
  /// empty set of 0 states) when out of range.
  bool reset(Eigen::Index n_states);

  /// Appends one group (one frequency): rows e_{others[r]}' - e_{reference}'. False, with nothing
  /// appended, when an index is outside [0, n_states), repeats within the group, equals the
  /// reference, already appears in an earlier group (as reference or satellite: groups must be
  /// disjoint, or G loses rank), or the set would exceed kMaxAmbiguities. An empty `others` with
  /// a valid reference appends nothing and returns true (a frequency with one satellite).
  bool add_group(Eigen::Index reference, std::span<const Eigen::Index> others);

  /// Filter states n_x of the current set.
  [[nodiscard]] Eigen::Index states() const { return n_states_; }
  /// DD ambiguities k.
  [[nodiscard]] Eigen::Index size() const { return size_; }
  /// State index of row `row`'s reference satellite (0 <= row < size()).
  [[nodiscard]] Eigen::Index reference_of(Eigen::Index row) const;
  /// State index of row `row`'s satellite (0 <= row < size()).
  [[nodiscard]] Eigen::Index state_of(Eigen::Index row) const;

  /// a = G x [cycles], Q = G P G' [cycles^2] (exactly symmetric), PGt = P G' (n_x x k), by index.
  /// False (outputs unchanged) when x is not n_x or P not n_x x n_x. Allocates nothing.
  bool evaluate(const Eigen::Ref<const Eigen::VectorXd>& x, const Eigen::Ref<const Eigen::MatrixXd>& P);

  /// Views, valid after a successful evaluate() (G after reset/add_group).
  [[nodiscard]] Eigen::VectorBlock<const Eigen::VectorXd> a() const { return a_.head(size_); }
  [[nodiscard]] Eigen::Block<const Eigen::MatrixXd> Q() const { return Q_.topLeftCorner(size_, size_); }
  [[nodiscard]] Eigen::Block<const Eigen::MatrixXd> PGt() const { return PGt_.topLeftCorner(n_states_, size_); }
  /// k x n_x, dense (two non-zeros per row).
  [[nodiscard]] Eigen::Block<const Eigen::MatrixXd> G() const { return G_.topLeftCorner(size_, n_states_); }

 private:
  explicit DoubleDifferenceAmbiguities(Eigen::Index max_states);
  [[nodiscard]] bool in_use(Eigen::Index state) const;
  [[nodiscard]] bool group_is_valid(Eigen::Index reference, std::span<const Eigen::Index> others) const;

  Eigen::Index max_states_ = 0;
  Eigen::Index n_states_ = 0;
  Eigen::Index size_ = 0;
  std::array<Eigen::Index, kMaxAmbiguities> reference_{};  // per row: state index of the reference
  std::array<Eigen::Index, kMaxAmbiguities> state_{};      // per row: state index of the satellite
  std::array<Eigen::Index, kMaxAmbiguities> groups_{};     // per group: its reference (for in_use)
  Eigen::Index group_count_ = 0;
  Eigen::MatrixXd G_;    // kMaxAmbiguities x max_states
  Eigen::VectorXd a_;    // kMaxAmbiguities
  Eigen::MatrixXd Q_;    // kMaxAmbiguities x kMaxAmbiguities
  Eigen::MatrixXd PGt_;  // max_states x kMaxAmbiguities
};

}  // namespace visors::nav
