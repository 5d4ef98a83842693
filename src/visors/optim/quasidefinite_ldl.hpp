#pragma once
// LDL' factorisation of a symmetric quasi-definite matrix [H  A'; A  -D] (H, D positive
// definite), the reduced KKT matrix of the conic solver. A quasi-definite matrix has an LDL'
// factorisation for every symmetric ordering (Vanderbei 1995, "Symmetric quasi-definite
// matrices", SIAM J. Optim. 5(1), thm 2.1), so no pivoting is needed and the structure of L is
// known before the numbers: analyse() computes the fill of L from the structural non-zeros
// marked by the caller, and factor() then touches only those entries (dense storage, sparse
// work). Storage is sized once for the largest matrix; nothing here allocates after
// construction.
//
// Dynamic regularisation (ECOS, Domahidi et al. 2013 sec. 5.2): a pivot whose sign is wrong or
// whose magnitude is below `epsilon` is replaced by sign * delta.

#include <cstddef>
#include <vector>

namespace visors::optim {

class QuasiDefiniteLdl {
 public:
  QuasiDefiniteLdl() = default;
  explicit QuasiDefiniteLdl(int capacity);

  /// Starts a new structure of dimension `size` whose first `positive` pivots are > 0 and the
  /// rest < 0. Clears the marks.
  void begin_structure(int size, int positive);
  /// Marks (i, j), i >= j, as a structural non-zero.
  void mark(int i, int j) { pattern_[index(i, j)] = 1; }
  /// Computes the fill of L (symbolic factorisation).
  void analyse();

  /// Zeroes every structural entry (before assembling new values).
  void clear_values();
  /// Entry (i, j) of the lower triangle, i >= j; must have been marked.
  double& at(int i, int j) { return value_[index(i, j)]; }

  /// Factors in place; returns the number of regularised pivots, or -1 on a non-finite pivot.
  int factor(double epsilon, double delta);
  /// Solves L D L' x = rhs in place.
  void solve(double* x) const;

  [[nodiscard]] int size() const { return size_; }

 private:
  [[nodiscard]] std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(i) * static_cast<std::size_t>(capacity_) +
           static_cast<std::size_t>(j);
  }

  int capacity_ = 0;
  int size_ = 0;
  int positive_ = 0;
  std::vector<unsigned char> pattern_;  // lower triangle, row-major, capacity x capacity
  std::vector<double> value_;           // matrix, then L (unit diagonal implied) in place
  std::vector<double> diag_;            // D
  std::vector<int> col_ptr_;            // rows i > j with L(i, j) structurally non-zero
  std::vector<int> col_rows_;
  std::vector<double> col_vals_;        // L(col_rows_[a], j), contiguous per column for solve()
};

}  // namespace visors::optim
