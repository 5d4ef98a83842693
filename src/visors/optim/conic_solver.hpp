#pragma once
// Embedded primal-dual interior-point solver for the conic programs of conic_problem.hpp (LP,
// SOCP, QP), in the family of ECOS (Domahidi, Chu & Boyd 2013) and CVXOPT's conelp
// (Vandenberghe 2010):
// - homogeneous self-dual embedding (tau, kappa), so infeasibility and unboundedness end with
//   certificates; the quadratic objective is handled natively in the embedding (the x'Px/tau
//   term of Goulart & Chen 2024, Clarabel), not by an SOC reformulation;
// - Nesterov-Todd scaling, Mehrotra predictor-corrector (sigma = (1 - alpha_aff)^3);
// - Ruiz equilibration of [A; G] (SOC blocks scaled as a whole);
// - KKT: the reduced quasi-definite system [P + G'W^-2 G + dI, A'; A, -dI] (static
//   regularisation d), factored by a structure-aware LDL' with dynamic regularisation
//   (quasidefinite_ldl.hpp); iterative refinement against the exact, unregularised, unreduced
//   system; when a pivot had to be regularised or the refinement stalls, that iteration uses a
//   dense LU with partial pivoting of the same matrix instead.
// - Separable cone blocks (each row one entry of G, in columns no other block or P touches:
//   variable bounds, norm cones on variables as in the planners' ||dv_k|| <= t_k) are eliminated
//   in closed form before the LDL' (their diagonal block G_k'W_k^-2 G_k has the explicit inverse
//   G_k^-1 W_k^2 G_k^-T), so the LDL' never pivots on those blocks, whose condition is that of
//   W_k squared near the optimum; there the dense LU fallback becomes rare.
// - When every column is separable (the planners' minimum-fuel problems), the whole KKT solve is
//   the p x p Schur complement of separable_kkt.hpp, unregularised and exact.
// Stopping tests and tolerances: conic_settings.hpp. Notes: docs/algorithms/control.md#conic-solver.
//
// All storage is sized by create(); solve() allocates nothing on accepted data (a rejected input
// builds its error message), and may be called again with new data of the same dimensions.

#include <memory>
#include <string_view>

#include <Eigen/Core>

#include "visors/core/status.hpp"
#include "visors/optim/conic_problem.hpp"
#include "visors/optim/conic_settings.hpp"

namespace visors::optim {

enum class ConicStatus { kOptimal, kPrimalInfeasible, kDualInfeasible, kMaxIterations, kNumericalError };

/// "optimal", "primal_infeasible", "dual_infeasible", "max_iterations", "numerical_error".
std::string_view to_string(ConicStatus status);

struct ConicInfo {
  ConicStatus status = ConicStatus::kNumericalError;
  int iterations = 0;
  /// (1/2) x'Px + c'x and the dual objective; +inf both when primal infeasible, -inf both when
  /// dual infeasible.
  double primal_objective = 0.0;
  double dual_objective = 0.0;
  double primal_residual = 0.0;  // the stopping quantities of ConicSettings, last iterate
  double dual_residual = 0.0;
  double gap = 0.0;
  /// Iterations whose KKT systems went to the dense pivoted LU fallback (diagnostic).
  int dense_fallbacks = 0;
};

class ConicSolver {
 public:
  /// Sizes every buffer for problems of dimensions `dims`.
  static core::Result<ConicSolver> create(const ConicDimensions& dims, const ConicSettings& settings = {});

  /// Solves `problem` (dimensions as at create()). Optimal or stopped: x, y, z, s are the
  /// iterate. Primal infeasible: y, z certify it (b'y + h'z = -1, A'y + G'z ~ 0, z in K) and
  /// x = s = 0. Dual infeasible: x, s certify it (c'x = -1, Ax ~ 0, Gx + s ~ 0, s in K, Px ~ 0)
  /// and y = z = 0.
  core::Outcome<ConicInfo> solve(const ConicProblem& problem);

  [[nodiscard]] const Eigen::VectorXd& x() const { return x_out_; }
  [[nodiscard]] const Eigen::VectorXd& y() const { return y_out_; }
  [[nodiscard]] const Eigen::VectorXd& z() const { return z_out_; }
  [[nodiscard]] const Eigen::VectorXd& s() const { return s_out_; }
  [[nodiscard]] const ConicDimensions& dimensions() const { return dims_; }
  [[nodiscard]] const ConicSettings& settings() const { return settings_; }

  ConicSolver(ConicSolver&&) noexcept;
  ConicSolver& operator=(ConicSolver&&) noexcept;
  ~ConicSolver();

 private:
  struct Workspace;
  ConicSolver(const ConicDimensions& dims, const ConicSettings& settings);

  ConicDimensions dims_;
  ConicSettings settings_;
  std::unique_ptr<Workspace> work_;  // pimpl keeps the header small
  Eigen::VectorXd x_out_, y_out_, z_out_, s_out_;
};

}  // namespace visors::optim
