#include "visors/optim/quasidefinite_ldl.hpp"

#include <cmath>

namespace visors::optim {

QuasiDefiniteLdl::QuasiDefiniteLdl(int capacity)
    : capacity_(capacity),
      pattern_(static_cast<std::size_t>(capacity) * static_cast<std::size_t>(capacity), 0),
      value_(static_cast<std::size_t>(capacity) * static_cast<std::size_t>(capacity), 0.0),
      diag_(static_cast<std::size_t>(capacity), 0.0),
      col_ptr_(static_cast<std::size_t>(capacity) + 1, 0),
      col_rows_(static_cast<std::size_t>(capacity) * static_cast<std::size_t>(capacity) / 2 + 1, 0),
      col_vals_(col_rows_.size(), 0.0) {}

void QuasiDefiniteLdl::begin_structure(int size, int positive) {
  size_ = size;
  positive_ = positive;
  for (int i = 0; i < size_; ++i) {
    for (int j = 0; j <= i; ++j) pattern_[index(i, j)] = 0;
    pattern_[index(i, i)] = 1;
  }
}

void QuasiDefiniteLdl::analyse() {
  // Right-looking symbolic elimination: eliminating column j couples every pair of its rows.
  int count = 0;
  for (int j = 0; j < size_; ++j) {
    col_ptr_[j] = count;
    for (int i = j + 1; i < size_; ++i) {
      if (pattern_[index(i, j)] != 0) col_rows_[count++] = i;
    }
    for (int a = col_ptr_[j]; a < count; ++a) {
      for (int b = col_ptr_[j]; b <= a; ++b) pattern_[index(col_rows_[a], col_rows_[b])] = 1;
    }
  }
  col_ptr_[size_] = count;
}

void QuasiDefiniteLdl::clear_values() {
  for (int j = 0; j < size_; ++j) {
    value_[index(j, j)] = 0.0;
    for (int a = col_ptr_[j]; a < col_ptr_[j + 1]; ++a) value_[index(col_rows_[a], j)] = 0.0;
  }
}

int QuasiDefiniteLdl::factor(double epsilon, double delta) {
  int regularised = 0;
  for (int j = 0; j < size_; ++j) {
    double d = value_[index(j, j)];
    if (!std::isfinite(d)) return -1;
    const double sign = j < positive_ ? 1.0 : -1.0;
    if (sign * d <= epsilon) {
      d = sign * delta;
      ++regularised;
    }
    diag_[j] = d;
    const int begin = col_ptr_[j];
    const int end = col_ptr_[j + 1];
    // Schur complement update with the unscaled column, then scale it into L.
    for (int a = begin; a < end; ++a) {
      const int k = col_rows_[a];
      const double lkj = value_[index(k, j)] / d;
      if (lkj == 0.0) continue;
      for (int b = a; b < end; ++b) {
        const int i = col_rows_[b];
        value_[index(i, k)] -= value_[index(i, j)] * lkj;
      }
    }
    for (int a = begin; a < end; ++a) {
      value_[index(col_rows_[a], j)] /= d;
      col_vals_[a] = value_[index(col_rows_[a], j)];
    }
  }
  return regularised;
}

void QuasiDefiniteLdl::solve(double* x) const {
  for (int j = 0; j < size_; ++j) {
    const double xj = x[j];
    if (xj == 0.0) continue;
    for (int a = col_ptr_[j]; a < col_ptr_[j + 1]; ++a) x[col_rows_[a]] -= col_vals_[a] * xj;
  }
  for (int j = 0; j < size_; ++j) x[j] /= diag_[j];
  for (int j = size_ - 1; j >= 0; --j) {
    double sum = x[j];
    for (int a = col_ptr_[j]; a < col_ptr_[j + 1]; ++a) sum -= col_vals_[a] * x[col_rows_[a]];
    x[j] = sum;
  }
}

}  // namespace visors::optim
