#pragma once
// Fuel-optimal impulsive reconfiguration in mean QNS ROE with the reachable-set (dual) algorithm of
// Koenig & D'Amico, "Fast algorithm for fuel-optimal impulsive control of linear systems with
// time-varying cost", IEEE TAC 2021 (KD21); docs/algorithms/control.md#reachable-set-planner.
//
// Problem (docs/algorithms/control.md#the-linear-model): with the pseudostate
// w = roe_target - Phi(tf, t0) roe0,
//   minimise sum_j ||dv_j||  s.t.  sum_j Phi(tf, t_j) Gamma(t_j) dv_j = w,  t_j in [t_earliest, tf],
// Phi = astro::j2_roe_stm from the chief's mean elements at t_j (J2 secular propagation),
// Gamma = astro::control_input_matrix (eccentric form) at t_j.
//
// Why the dual: the primal over a grid of K candidate times has 4K variables and K cones, while
// the dual  max lambda'w  s.t.  ||B_k' lambda|| <= 1 (B_k = Phi Gamma at grid time k)  has six
// variables whatever K is. KD21's iteration keeps only a small working set of the constraints
// (the ones the current lambda makes active or violates), so each SOCP has a fixed, small size
// and the grid can be fine: the grid only costs the 6x3 evaluation of ||B_k' lambda|| per point.
// Steps of plan():
//  1. B_k on `grid_points` equally spaced times over [t_earliest, tf] (metres and seconds, scaled
//     by the mean motion so the SOCP data are O(1); w normalised to unit length).
//  2. Exchange iteration (KD21): restricted dual SOCP over the working set (fixed
//     anchors spread over the window, so the dual stays bounded, plus the previously active and
//     the most violated grid constraints); stop when max_k ||B_k' lambda|| <= 1 + tolerance.
//     lambda / max_k ||B_k' lambda|| is dual feasible for the whole grid at every iteration, so
//     lambda'w / max_k h_k is a lower bound on the grid optimum (ManeuverPlan::dv_lower_bound).
//  3. Impulse times: the local maxima of h(t) = ||B(t)' lambda|| that reach 1 (the contact points
//     of the reachable set's supporting hyperplane), each refined off the grid by a parabola
//     through its three grid values.
//  4. Magnitudes: a small primal SOCP min sum ||dv_j|| s.t. sum B_j dv_j = w over those times
//     only (it also absorbs the direction error of the time quantisation), a Caratheodory
//     reduction to at most 6 impulses (a basic solution of the LP in the impulse scales, cost
//     unchanged); below 6, `max_impulses` is a cardinality constraint the convex problem does not
//     have: 1 = the best single impulse on the grid if it reaches the target (in general it
//     cannot), 2 = exhaustive search over the grid's pairs of times, 3-5 = greedy elimination from
//     the optimal support or the best pair, whichever is cheaper. Then a minimum-norm correction
//     that makes the linear terminal error round-off small (the SOCP meets its equality only to
//     its tolerance).
//  5. The plan, rejected (status "solver") if the linear model's terminal state still misses the
//     target by more than terminal_tolerance_m: never ok with a miss.
//
// Notes:
//  * The cone multipliers of the restricted dual are the primal impulses: with the ConicSolver
//    form (G x + s = h, dual G'z + c = 0), G rows [0; -B_k'] and c = -w they are exactly
//    dv_k = -z_k(1:3), s_k = z_k0 (in the normalised units; the dense-grid reference of
//    tests/control/test_reachable_set_planner.cpp checks the recovered impulses' feasibility).
//  * The times come from the restricted primal's support plus the refined peaks of h, not from
//    the peaks alone: two distinct burns one grid step apart both carry impulse but make one peak
//    of h (standby -> science over 1.5 orbits has such a pair).
//  * The grid primal (4K variables) is fast only with a sparse KKT, which ConicSolver does not
//    have (dense G); hence the dual with a working set.
//
// Allocation: create() sizes every buffer (grid, working set, one small solver per candidate
// count); plan() allocates only the returned impulse vector (and error messages); plan_into() nothing.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"
#include "visors/optim/conic_settings.hpp"

namespace visors::control {

struct ReachableSetSettings {
  /// Candidate impulse times, equally spaced over [t_earliest, tf] with both ends included.
  /// 241 gives 24 s steps over one orbit of the VISORS chief (the grid costs ~1 us per point).
  int grid_points = 241;
  /// Constraints in the restricted dual SOCP: `anchor_points` fixed, equally spaced grid times
  /// (they span R^6 on any window longer than ~0.1 orbit, which keeps the dual bounded) plus
  /// working slots for the active and violated constraints (at most 6 are active at the optimum,
  /// several violated peaks are added per iteration).
  int working_set_size = 28;
  int anchor_points = 12;
  /// Caratheodory: in R^6 an optimal plan needs at most 6 impulses. Fewer is a cardinality
  /// constraint (step 4 above): 1 reaches only special targets, 2 is exhaustive over the grid
  /// (grid_points^2 / 2 small solves: ~10 ms at 241), 3-5 greedy.
  int max_impulses = 6;
  /// Contact-time candidates passed to the magnitude SOCP (peaks of h above 1 - contact_tolerance).
  int max_candidates = 16;
  int max_exchange_iterations = 30;
  /// Stop the exchange when max_k h_k <= 1 + dual_tolerance: the restricted optimum is then
  /// within this relative margin of the grid optimum.
  double dual_tolerance = 1e-7;
  /// Peaks of h above 1 - contact_tolerance are impulse-time candidates; working-set constraints
  /// below 1 - contact_tolerance are dropped as inactive.
  double contact_tolerance = 2e-3;
  /// Shortest accepted horizon tf - t_earliest, in chief orbits. Below ~0.1 orbit a general 6-D
  /// target needs impulses whose cost grows like 1/horizon^2 (the B(t) are nearly parallel).
  double min_horizon_orbits = 0.1;
  /// Box |lambda_i| <= dual_box on the scaled dual (scaled cost = lambda'w in units of n |a w|;
  /// typical reconfigurations have O(1)). A box constraint that binds means the target is
  /// (practically) unreachable in the window: the cost would exceed ~dual_box n |a w|.
  double dual_box = 1e3;
  /// Largest accepted terminal miss of a plan in the linear model, |a (roe_f - roe_target)| [m].
  double terminal_tolerance_m = 1e-3;
  core::EarthGravityConstants gravity{};
  optim::ConicSettings solver{};
};

/// Diagnostics of the last plan() call.
struct ReachableSetStats {
  int exchange_iterations = 0;
  int socp_iterations = 0;       // interior-point iterations, all SOCPs of the call
  int candidates = 0;            // contact times passed to the magnitude SOCP
  double max_dual_violation = 0.0;  // max_k h_k - 1 at the last exchange iteration
  double grid_dual_objective = 0.0;  // lambda'w of the last restricted dual [m/s]
};

class ReachableSetPlanner {
 public:
  /// Validates the settings (the field is named: "grid_points", "working_set_size", ...) and sizes
  /// every buffer and conic solver.
  static core::Result<ReachableSetPlanner> create(const ReachableSetSettings& settings = {});

  /// Plans impulses at times in [t_earliest, tf] (seconds since the chief epoch t0) that take the
  /// mean ROE from roe0 (at t0) to roe_target (at tf). Errors: "chief_mean_t0" (invalid elements),
  /// "roe0"/"roe_target" (non-finite), "t_earliest"/"tf" (non-finite, t_earliest < 0,
  /// tf <= t_earliest), "horizon" (shorter than min_horizon_orbits), "roe_target" (unreachable:
  /// the dual box binds), "solver" (an SOCP did not converge).
  core::Result<ManeuverPlan> plan(const astro::KeplerianElements& chief_mean_t0,
                                  const astro::RelativeOrbitalElements& roe0,
                                  const astro::RelativeOrbitalElements& roe_target, double t_earliest,
                                  double tf);
  /// The same into `result` (its impulse vector cleared and refilled: with capacity for
  /// max_impulses, nothing is allocated). On error `result` is unspecified.
  core::Status plan_into(ManeuverPlan& result, const astro::KeplerianElements& chief_mean_t0,
                               const astro::RelativeOrbitalElements& roe0,
                               const astro::RelativeOrbitalElements& roe_target, double t_earliest, double tf);

  [[nodiscard]] const ReachableSetSettings& settings() const { return settings_; }
  [[nodiscard]] const ReachableSetStats& stats() const { return stats_; }

  ReachableSetPlanner(ReachableSetPlanner&&) noexcept;
  ReachableSetPlanner& operator=(ReachableSetPlanner&&) noexcept;
  ~ReachableSetPlanner();

 private:
  struct Problem;
  struct Workspace;
  using Effect = Eigen::Matrix<double, 6, 3>;
  explicit ReachableSetPlanner(const ReachableSetSettings& settings);

  // The phases of plan_into, in order (steps of the file comment).
  core::Status validate_inputs(const astro::KeplerianElements& chief_mean_t0,
                                     const astro::RelativeOrbitalElements& roe0,
                                     const astro::RelativeOrbitalElements& roe_target, double t_earliest,
                                     double tf) const;
  void build_grid(Problem& pb, double t_earliest);
  core::Status screen_reachability(const Problem& pb) const;
  core::Status exchange_iteration(const Problem& pb);
  void update_working_set();
  bool is_local_max(int k) const;
  void collect_candidates(const Problem& pb);
  void add_candidate(double t, const Effect& b);
  core::Outcome<double> solve_fixed_times(const Problem& pb, int m, int skip, std::vector<Eigen::Vector3d>& dv_out);
  core::Status solve_magnitudes(const Problem& pb);
  void reduce_to_six();
  core::Status reduce_to_max_impulses(const Problem& pb);
  core::Status best_single_impulse(const Problem& pb);
  core::Status best_impulse_pair(const Problem& pb, double cost_to_beat);
  void correct_terminal_residual(const Problem& pb);
  core::Status emit_plan(const Problem& pb, const astro::RelativeOrbitalElements& drift,
                               ManeuverPlan& result) const;

  ReachableSetSettings settings_;
  ReachableSetStats stats_;
  std::unique_ptr<Workspace> work_;
};

}  // namespace visors::control
