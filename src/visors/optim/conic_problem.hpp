#pragma once
// Data of a conic program in the standard form of CVXOPT and ECOS (Vandenberghe 2010, eq. (1)):
//   minimise (1/2) x'Px + c'x  subject to  A x = b,  G x + s = h,  s in K,
// K = R+^l x Q^{q1} x ... (cone.hpp). P is optional (a convex quadratic objective).

#include <vector>

#include <Eigen/Core>

#include "visors/core/status.hpp"

namespace visors::optim {

/// Dimensions fixed when a solver is set up.
struct ConicDimensions {
  int n = 0;               // variables
  int p = 0;               // equality rows (0 allowed)
  int l = 0;               // orthant rows of G
  std::vector<int> q;      // second-order cone dimensions, each >= 1
  bool quadratic = false;  // whether P is present

  /// Rows of G and h: l + sum(q).
  [[nodiscard]] int m() const;
};

/// Problem data, dense (the sizes of the on-board planners do not call for sparse input; the
/// solver exploits the zero structure internally). An empty P means no quadratic term.
struct ConicProblem {
  Eigen::VectorXd c;
  Eigen::MatrixXd G;
  Eigen::VectorXd h;
  Eigen::MatrixXd A;  // p x n, may be 0 x n
  Eigen::VectorXd b;
  Eigen::MatrixXd P;  // n x n symmetric PSD, or 0 x 0
};

/// Checks the dimensions themselves (n >= 1, p >= 0, l >= 0, every q_k >= 1).
core::Status validate_dimensions(const ConicDimensions& dims);

/// Checks the data against `dims`: sizes, finiteness, P symmetric (relative tolerance
/// `symmetry_tolerance`). Names the field ("G", "h", "P", ...) on rejection. Positive
/// semidefiniteness of P is checked by the solver's factorisation of P.
core::Status validate_problem(const ConicProblem& problem, const ConicDimensions& dims,
                                    double symmetry_tolerance = 1e-12);

}  // namespace visors::optim
