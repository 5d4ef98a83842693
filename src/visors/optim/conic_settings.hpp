#pragma once
// Tunables of the interior-point conic solver, with their defaults and why.

namespace visors::optim {

struct ConicSettings {
  /// Iteration cap. Interior-point methods on these sizes converge in 10-30 iterations; 100
  /// leaves room for badly scaled data while bounding the on-board run time.
  int max_iterations = 100;
  /// Stopping tests (Vandenberghe 2010 sec. 7, the CVXOPT conelp tests), on the unscaled data,
  /// with x, y, z, s divided by tau:
  ///   primal residual  max(||Ax - b|| / max(1, ||b||), ||Gx + s - h|| / max(1, ||h||))
  ///   dual residual    ||P x + A'y + G'z + c|| / max(1, ||c||)      both <= feasibility_tolerance
  ///   and gap s'z <= absolute_gap_tolerance or gap / |objective| <= relative_gap_tolerance.
  /// Certificates: primal infeasible when b'y + h'z < 0 and ||A'y + G'z|| / max(1, ||c||)
  /// <= feasibility_tolerance * (-(b'y + h'z)); dual infeasible (unbounded) when c'x < 0 and
  /// max(||Ax|| / max(1, ||b||), ||Gx + s|| / max(1, ||h||), ||Px|| / max(1, ||c||))
  /// <= feasibility_tolerance * (-c'x). Gap s'z and objectives use x/tau, s/tau, z/tau.
  double feasibility_tolerance = 1e-8;
  double absolute_gap_tolerance = 1e-8;
  double relative_gap_tolerance = 1e-8;
  /// Fraction of the distance to the cone boundary taken by a step (ECOS and CVXOPT: 0.99).
  double step_fraction = 0.99;
  /// Static regularisation delta of the reduced KKT matrix [H + delta I, A'; A, -delta I]
  /// (quasi-definite for any A); the refinement removes its effect from the solution.
  double static_regularisation = 1e-9;
  /// Dynamic regularisation: a pivot of the wrong sign or below epsilon becomes sign * delta.
  double dynamic_epsilon = 1e-13;
  double dynamic_delta = 1e-7;
  /// Maximum iterative refinement steps against the unregularised, unreduced KKT system (a solve
  /// stops early once the relative residual is below refinement_tolerance or a step no longer
  /// halves it). 1e-12 keeps the CVXOPT agreement of tests/optim/test_conic_oracle.cpp and the
  /// reachable-set planner's restricted dual SOCPs (closed-loop MPC test) with margin.
  int refinement_steps = 10;
  double refinement_tolerance = 1e-12;
  /// Ruiz equilibration passes over [A; G] (0 disables it).
  int equilibration_passes = 10;
  /// Relative tolerance of the PSD check of P (pivoted Cholesky).
  double psd_tolerance = 1e-10;
};

}  // namespace visors::optim
