#include "visors/optim/conic_problem.hpp"

#include <cmath>

namespace visors::optim {
namespace {

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

core::Status validate_dimensions(const ConicDimensions& dims) {
  if (dims.n < 1) return core::Status{core::Problem::kOutOfRange, "dims.n", "must be >= 1"};
  if (dims.p < 0) return core::Status{core::Problem::kOutOfRange, "dims.p", "must be >= 0"};
  if (dims.l < 0) return core::Status{core::Problem::kOutOfRange, "dims.l", "must be >= 0"};
  for (const int dim : dims.q) {
    if (dim < 1) return core::Status{core::Problem::kOutOfRange, "dims.q", "every cone's dimension must be >= 1"};
  }
  return {};
}

core::Status validate_problem(const ConicProblem& problem, const ConicDimensions& dims,
                                    double symmetry_tolerance) {
  const Eigen::Index n = dims.n;
  const Eigen::Index m = dims.m();
  const Eigen::Index p = dims.p;
  if (problem.c.size() != n) return core::Status{core::Problem::kInconsistent, "c", "must have n entries"};
  if (problem.G.rows() != m || problem.G.cols() != n) {
    return core::Status{core::Problem::kInconsistent, "G", "must be (l + sum(q)) x n"};
  }
  if (problem.h.size() != m) return core::Status{core::Problem::kInconsistent, "h", "must have l + sum(q) entries"};
  if (problem.A.rows() != p || (p > 0 && problem.A.cols() != n)) {
    return core::Status{core::Problem::kInconsistent, "A", "must be p x n"};
  }
  if (problem.b.size() != p) return core::Status{core::Problem::kInconsistent, "b", "must have p entries"};
  if (dims.quadratic) {
    if (problem.P.rows() != n || problem.P.cols() != n) {
      return core::Status{core::Problem::kInconsistent, "P", "must be n x n"};
    }
  } else if (problem.P.size() != 0) {
    return core::Status{core::Problem::kInconsistent, "P", "given but the solver was set up without a quadratic term"};
  }
  if (!all_finite(problem.c)) return core::Status{core::Problem::kNotFinite, "c", "must be finite"};
  if (!all_finite(problem.G)) return core::Status{core::Problem::kNotFinite, "G", "must be finite"};
  if (!all_finite(problem.h)) return core::Status{core::Problem::kNotFinite, "h", "must be finite"};
  if (!all_finite(problem.A)) return core::Status{core::Problem::kNotFinite, "A", "must be finite"};
  if (!all_finite(problem.b)) return core::Status{core::Problem::kNotFinite, "b", "must be finite"};
  if (dims.quadratic) {
    if (!all_finite(problem.P)) return core::Status{core::Problem::kNotFinite, "P", "must be finite"};
    const double scale = std::max(1.0, problem.P.cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < i; ++j) {
        if (std::abs(problem.P(i, j) - problem.P(j, i)) > symmetry_tolerance * scale) {
          return core::Status{core::Problem::kNotSymmetric, "P", "must be symmetric"};
        }
      }
    }
  }
  return {};
}

}  // namespace visors::optim
