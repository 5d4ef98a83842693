#include "visors/optim/conic_problem.hpp"

#include <cmath>
#include <string>

namespace visors::optim {
namespace {

std::string size_text(Eigen::Index rows, Eigen::Index cols) {
  return std::to_string(rows) + " x " + std::to_string(cols);
}

// Takes any dense expression by reference: a `const MatrixXd&` parameter would copy every vector
// passed to it (one heap allocation each, which solve() must not make).
template <typename Derived>
bool all_finite(const Eigen::DenseBase<Derived>& m) {
  return m.size() == 0 || m.allFinite();
}

}  // namespace

int ConicDimensions::m() const {
  int rows = l;
  for (const int dim : q) rows += dim;
  return rows;
}

core::Result<bool> validate_dimensions(const ConicDimensions& dims) {
  if (dims.n < 1) return core::Error{"dims.n", "must be >= 1"};
  if (dims.p < 0) return core::Error{"dims.p", "must be >= 0"};
  if (dims.l < 0) return core::Error{"dims.l", "must be >= 0"};
  for (std::size_t k = 0; k < dims.q.size(); ++k) {
    if (dims.q[k] < 1) return core::Error{"dims.q[" + std::to_string(k) + "]", "must be >= 1"};
  }
  return true;
}

core::Result<bool> validate_problem(const ConicProblem& problem, const ConicDimensions& dims,
                                    double symmetry_tolerance) {
  const Eigen::Index n = dims.n;
  const Eigen::Index m = dims.m();
  const Eigen::Index p = dims.p;
  if (problem.c.size() != n) return core::Error{"c", "must have n = " + std::to_string(n) + " entries"};
  if (problem.G.rows() != m || problem.G.cols() != n) {
    return core::Error{"G", "must be " + size_text(m, n) + " (rows = l + sum(q)), got " +
                                size_text(problem.G.rows(), problem.G.cols())};
  }
  if (problem.h.size() != m) return core::Error{"h", "must have l + sum(q) = " + std::to_string(m) + " entries"};
  if (problem.A.rows() != p || (p > 0 && problem.A.cols() != n)) {
    return core::Error{"A", "must be " + size_text(p, n) + ", got " +
                                size_text(problem.A.rows(), problem.A.cols())};
  }
  if (problem.b.size() != p) return core::Error{"b", "must have p = " + std::to_string(p) + " entries"};
  if (dims.quadratic) {
    if (problem.P.rows() != n || problem.P.cols() != n) {
      return core::Error{"P", "must be " + size_text(n, n)};
    }
  } else if (problem.P.size() != 0) {
    return core::Error{"P", "given but the solver was set up without a quadratic term"};
  }
  if (!all_finite(problem.c)) return core::Error{"c", "must be finite"};
  if (!all_finite(problem.G)) return core::Error{"G", "must be finite"};
  if (!all_finite(problem.h)) return core::Error{"h", "must be finite"};
  if (!all_finite(problem.A)) return core::Error{"A", "must be finite"};
  if (!all_finite(problem.b)) return core::Error{"b", "must be finite"};
  if (dims.quadratic) {
    if (!all_finite(problem.P)) return core::Error{"P", "must be finite"};
    const double scale = std::max(1.0, problem.P.cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < i; ++j) {
        if (std::abs(problem.P(i, j) - problem.P(j, i)) > symmetry_tolerance * scale) {
          return core::Error{"P", "must be symmetric"};
        }
      }
    }
  }
  return true;
}

}  // namespace visors::optim
