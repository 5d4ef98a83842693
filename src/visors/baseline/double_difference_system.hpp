#pragma once
// Double differences between satellites of the single differences of one epoch, as a linear
// system around the current rover position: y = H dx + noise, with dx = (rover position error
// [m], SD ambiguities [cycles]). One reference satellite per observable and frequency (the
// highest); for satellite i and reference k:
//   y_i = r_i - r_k                 (the SD residuals, single_difference.hpp)
//   H_i = [-(e_i - e_k)',  lambda at i's ambiguity, -lambda at k's]   (phase)
//   H_i = [-(e_i - e_k)',  0]                                         (code)
// (e the unit vector rover -> satellite: the range falls as the rover moves towards it). The
// DD noise is correlated through the reference
// (docs/algorithms/gnss-measurements.md#double-differences): within a group
// R_ij = s_k + delta_ij s_i (s the SD variances); groups are independent.

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "visors/baseline/single_difference.hpp"

namespace visors::baseline {

enum class Observable { kPhase, kCode };

inline constexpr int kMaxPrn = 32;
inline constexpr Eigen::Index kPositionStates = 3;
inline constexpr Eigen::Index kStates = kPositionStates + kFrequencies * kMaxPrn;  // 67

/// State index of the SD ambiguity of `prn` (1..32) on `frequency` (0 L1, 1 L2).
inline Eigen::Index ambiguity_index(int frequency, int prn) {
  return kPositionStates + static_cast<Eigen::Index>(frequency * kMaxPrn + prn - 1);
}

struct DdGroup {
  Observable kind = Observable::kPhase;
  int frequency = 0;
  int reference = -1;        // index of the reference in the single differences
  std::vector<int> members;  // the others (indices in the single differences)
};

struct DdRow {
  Observable kind = Observable::kPhase;
  int frequency = 0;
  int prn = 0;
  int reference_prn = 0;
};

struct DdSystem {
  Eigen::VectorXd y;  // [m]
  Eigen::MatrixXd H;  // rows x (3 or kStates)
  Eigen::MatrixXd R;  // [m^2]
  std::vector<DdRow> rows;
};

/// Groups of `kind` for each frequency: the satellites whose residual is present and that
/// `usable(index in sds, frequency)` accepts; the highest of them is the reference. Groups of
/// fewer than 2 satellites are left out.
std::vector<DdGroup> make_groups(const std::vector<SingleDifference>& sds, Observable kind,
                                 const std::function<bool(int, int)>& usable);

/// The system of `groups`; with_ambiguities: kStates columns, else the 3 position columns.
DdSystem build_dd_system(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& groups,
                         bool with_ambiguities);

}  // namespace visors::baseline
