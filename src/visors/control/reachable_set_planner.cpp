#include "visors/control/reachable_set_planner.hpp"
#include "visors/control/impulse_effect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/optim/conic_problem.hpp"
#include "visors/optim/conic_solver.hpp"

namespace visors::control {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

core::Error invalid(std::string field, std::string message) {
  return core::Error{std::move(field), std::move(message)};
}

std::size_t at(int k) { return static_cast<std::size_t>(k); }

// Restricted dual (docs/algorithms/control.md#reachable-set-planner), variables lambda (6):
// min -w'lambda s.t.
//   lambda_i <= L, -lambda_i <= L        (12 orthant rows: the box keeps every restriction bounded)
//   (1, B_k' lambda) in Q^4 per slot     (G rows [0; -B_k'], h = (1, 0, 0, 0))
optim::ConicDimensions dual_dimensions(int slots) {
  optim::ConicDimensions dims;
  dims.n = 6;
  dims.p = 0;
  dims.l = 12;
  dims.q.assign(static_cast<std::size_t>(slots), 4);
  return dims;
}

optim::ConicProblem dual_problem_shell(int slots, double dual_box) {
  optim::ConicProblem dpr;
  const int rows = 12 + 4 * slots;
  dpr.c = Eigen::VectorXd::Zero(6);
  dpr.G = Eigen::MatrixXd::Zero(rows, 6);
  dpr.G.topRows(6) = Eigen::MatrixXd::Identity(6, 6);
  dpr.G.middleRows(6, 6) = -Eigen::MatrixXd::Identity(6, 6);
  dpr.h = Eigen::VectorXd::Zero(rows);
  dpr.h.head(12).setConstant(dual_box);
  for (int k = 0; k < slots; ++k) dpr.h(12 + 4 * k) = 1.0;
  dpr.A.resize(0, 6);
  dpr.b.resize(0);
  return dpr;
}

// Magnitude SOCP over m fixed times (ECOS-style conic form): variables [dv_1..dv_m, s_1..s_m],
// min sum s_j s.t. sum B_j dv_j = w, (s_j, dv_j) in Q^4.
optim::ConicDimensions primal_dimensions(int m) {
  optim::ConicDimensions dims;
  dims.n = 4 * m;
  dims.p = 6;
  dims.l = 0;
  dims.q.assign(static_cast<std::size_t>(m), 4);
  return dims;
}

optim::ConicProblem primal_problem_shell(int m) {
  optim::ConicProblem pr;
  const int n = 4 * m;
  pr.c = Eigen::VectorXd::Zero(n);
  pr.c.tail(m).setOnes();
  pr.G = Eigen::MatrixXd::Zero(n, n);
  for (int j = 0; j < m; ++j) {
    pr.G(4 * j, 3 * m + j) = -1.0;
    for (int i = 0; i < 3; ++i) pr.G(4 * j + 1 + i, 3 * j + i) = -1.0;
  }
  pr.h = Eigen::VectorXd::Zero(n);
  pr.A = Eigen::MatrixXd::Zero(6, n);
  pr.b = Eigen::VectorXd::Zero(6);
  return pr;
}

bool usable(optim::ConicStatus status) {
  return status == optim::ConicStatus::kOptimal || status == optim::ConicStatus::kMaxIterations;
}

}  // namespace

// Scaled problem of one plan() call: everything the phases share.
struct ReachableSetPlanner::Problem {
  const astro::KeplerianElements* chief = nullptr;
  double tf = 0.0;
  double n = 0.0;             // chief mean motion [rad/s]
  double dt = 0.0;            // grid step [s]
  double w_norm = 0.0;        // |a w| [m]
  double dv_scale = 0.0;      // dv [m/s] = scaled dv * n |a w|
  Vector6 w_hat = Vector6::Zero();
};

struct ReachableSetPlanner::Workspace {
  using Effect = ReachableSetPlanner::Effect;
  // Grid (capacity settings.grid_points).
  std::vector<double> t_grid;
  std::vector<Effect> b_grid;  // n a Phi(tf, t_k) Gamma(t_k): dimensionless
  std::vector<double> h_grid;  // ||B_k' lambda||
  std::vector<int> anchors;
  std::vector<int> slots;       // dynamic working-set slots (grid indices)
  std::vector<int> next_slots;
  std::vector<int> peaks;       // scratch, capacity grid_points
  optim::ConicSolver dual_solver;
  optim::ConicProblem dual_problem;
  // Magnitude SOCPs, one per candidate count 1..max_candidates.
  std::vector<optim::ConicSolver> primal_solvers;
  std::vector<optim::ConicProblem> primal_problems;
  // Candidate impulses: time, effect, scaled dv; `count` of them in use.
  std::vector<double> cand_t;
  std::vector<Effect> cand_b;
  std::vector<Eigen::Vector3d> cand_dv;
  std::vector<Eigen::Vector3d> best_dv;  // scratch of the cardinality reduction
  std::vector<Eigen::Vector3d> trial_dv;
  int count = 0;
  Vector6 lambda = Vector6::Zero();
  double h_max = 0.0;

  Workspace(optim::ConicSolver dual, optim::ConicProblem dual_pr)
      : dual_solver(std::move(dual)), dual_problem(std::move(dual_pr)) {}

  int slot_grid_index(int j, int anchor_count) const { return j < anchor_count ? anchors[at(j)] : slots[at(j - anchor_count)]; }

  void remove_candidate(int j) {
    for (int r = j; r + 1 < count; ++r) {
      cand_t[at(r)] = cand_t[at(r + 1)];
      cand_b[at(r)] = cand_b[at(r + 1)];
      cand_dv[at(r)] = cand_dv[at(r + 1)];
    }
    --count;
  }
};

ReachableSetPlanner::ReachableSetPlanner(const ReachableSetSettings& settings) : settings_(settings) {}
ReachableSetPlanner::ReachableSetPlanner(ReachableSetPlanner&&) noexcept = default;
ReachableSetPlanner& ReachableSetPlanner::operator=(ReachableSetPlanner&&) noexcept = default;
ReachableSetPlanner::~ReachableSetPlanner() = default;

core::Result<ReachableSetPlanner> ReachableSetPlanner::create(const ReachableSetSettings& s) {
  if (s.grid_points < 16 || s.grid_points > 100000) return invalid("grid_points", "must be in [16, 100000]");
  if (s.anchor_points < 7 || s.anchor_points > s.grid_points) {
    return invalid("anchor_points", "must be in [7, grid_points] (the anchors must span R^6)");
  }
  if (s.working_set_size < s.anchor_points + 6) {
    return invalid("working_set_size", "must leave at least 6 slots beyond anchor_points");
  }
  if (s.max_impulses < 1 || s.max_impulses > 6) return invalid("max_impulses", "must be in [1, 6]");
  if (s.max_candidates < s.max_impulses || s.max_candidates > 64) {
    return invalid("max_candidates", "must be in [max_impulses, 64]");
  }
  if (s.max_exchange_iterations < 1) return invalid("max_exchange_iterations", "must be >= 1");
  if (!(s.dual_tolerance > 0.0 && s.dual_tolerance < 0.1)) return invalid("dual_tolerance", "must be in (0, 0.1)");
  if (!(s.contact_tolerance > 0.0 && s.contact_tolerance < 0.5)) {
    return invalid("contact_tolerance", "must be in (0, 0.5)");
  }
  if (!(s.min_horizon_orbits >= 0.0 && std::isfinite(s.min_horizon_orbits))) {
    return invalid("min_horizon_orbits", "must be finite and >= 0");
  }
  if (!(s.dual_box > 1.0 && std::isfinite(s.dual_box))) return invalid("dual_box", "must be finite and > 1");
  if (!(s.terminal_tolerance_m > 0.0 && std::isfinite(s.terminal_tolerance_m))) {
    return invalid("terminal_tolerance_m", "must be finite and > 0");
  }
  if (!(s.gravity.mu > 0.0 && s.gravity.re > 0.0 && std::isfinite(s.gravity.j2))) {
    return invalid("gravity", "mu and re must be > 0, j2 finite");
  }

  auto dual = optim::ConicSolver::create(dual_dimensions(s.working_set_size), s.solver);
  if (!dual.ok()) return invalid("solver", dual.error().describe());
  ReachableSetPlanner planner(s);
  planner.work_ =
      std::make_unique<Workspace>(std::move(dual).value(), dual_problem_shell(s.working_set_size, s.dual_box));
  Workspace& w = *planner.work_;
  const auto grid = static_cast<std::size_t>(s.grid_points);
  w.t_grid.assign(grid, 0.0);
  w.b_grid.assign(grid, Effect::Zero());
  w.h_grid.assign(grid, 0.0);
  w.peaks.reserve(grid);
  w.anchors.assign(static_cast<std::size_t>(s.anchor_points), 0);
  w.slots.reserve(static_cast<std::size_t>(s.working_set_size));
  w.next_slots.reserve(static_cast<std::size_t>(s.working_set_size));
  w.primal_solvers.reserve(static_cast<std::size_t>(s.max_candidates));
  w.primal_problems.reserve(static_cast<std::size_t>(s.max_candidates));
  for (int m = 1; m <= s.max_candidates; ++m) {
    auto solver = optim::ConicSolver::create(primal_dimensions(m), s.solver);
    if (!solver.ok()) return invalid("solver", solver.error().describe());
    w.primal_solvers.push_back(std::move(solver).value());
    w.primal_problems.push_back(primal_problem_shell(m));
  }
  const auto cands = static_cast<std::size_t>(s.max_candidates);
  w.cand_t.assign(cands, 0.0);
  w.cand_b.assign(cands, Effect::Zero());
  w.cand_dv.assign(cands, Eigen::Vector3d::Zero());
  w.best_dv.assign(cands, Eigen::Vector3d::Zero());
  w.trial_dv.assign(cands, Eigen::Vector3d::Zero());
  return planner;
}

core::Result<ManeuverPlan> ReachableSetPlanner::plan(const astro::KeplerianElements& chief_mean_t0,
                                                     const astro::RelativeOrbitalElements& roe0,
                                                     const astro::RelativeOrbitalElements& roe_target,
                                                     double t_earliest, double tf) {
  ManeuverPlan result;
  result.impulses.reserve(static_cast<std::size_t>(settings_.max_impulses));
  if (auto ok = plan_into(result, chief_mean_t0, roe0, roe_target, t_earliest, tf); !ok) return ok.error();
  return result;
}

core::Status ReachableSetPlanner::plan_into(ManeuverPlan& result, const astro::KeplerianElements& chief_mean_t0,
                                                  const astro::RelativeOrbitalElements& roe0,
                                                  const astro::RelativeOrbitalElements& roe_target, double t_earliest,
                                                  double tf) {
  result.impulses.clear();
  result.dv_total_mps = 0.0;
  result.dv_lower_bound_mps = 0.0;
  stats_ = ReachableSetStats{};
  if (auto ok = validate_inputs(chief_mean_t0, roe0, roe_target, t_earliest, tf); !ok) return ok;

  // Pseudostate in metres, normalised.
  const double a = chief_mean_t0.a;
  const astro::RelativeOrbitalElements drift = astro::j2_roe_stm(chief_mean_t0, tf, settings_.gravity) * roe0;
  const Vector6 w_m = a * (roe_target - drift);
  result.roe_final_predicted = drift;
  Problem pb;
  pb.chief = &chief_mean_t0;
  pb.tf = tf;
  pb.n = std::sqrt(settings_.gravity.mu / (a * a * a));
  pb.w_norm = w_m.norm();
  if (!std::isfinite(pb.w_norm)) return core::Status{core::Problem::kNotFinite, "roe_target", "pseudostate is not finite"};
  if (pb.w_norm <= 1e-12 * a * std::max(roe_target.norm(), 1e-9)) return {};  // already on target
  pb.w_hat = w_m / pb.w_norm;
  // dv [m/s] = (scaled dv) * n * |a w|: sum (n B_k)(dv_k / (n |a w|)) = a w / |a w|.
  pb.dv_scale = pb.n * pb.w_norm;

  build_grid(pb, t_earliest);
  if (auto ok = screen_reachability(pb); !ok) return ok;
  if (auto ok = exchange_iteration(pb); !ok) return ok;
  // lambda / h_max is feasible for every grid constraint: weak duality gives the bound.
  Workspace& w = *work_;
  result.dv_lower_bound_mps = std::max(0.0, pb.w_hat.dot(w.lambda) / w.h_max) * pb.dv_scale;
  collect_candidates(pb);
  if (w.count == 0) return core::Status{core::Problem::kNotConverged, "solver", "no contact time found"};
  stats_.candidates = w.count;
  if (auto ok = solve_magnitudes(pb); !ok) return ok;
  reduce_to_six();
  if (w.count > settings_.max_impulses) {
    if (auto ok = reduce_to_max_impulses(pb); !ok) return ok;
  }
  correct_terminal_residual(pb);
  return emit_plan(pb, drift, result);
}

core::Status ReachableSetPlanner::validate_inputs(const astro::KeplerianElements& chief_mean_t0,
                                                        const astro::RelativeOrbitalElements& roe0,
                                                        const astro::RelativeOrbitalElements& roe_target,
                                                        double t_earliest, double tf) const {
  const auto chief_ok = astro::validate_keplerian(chief_mean_t0);
  if (!chief_ok.ok()) return chief_ok.status().within("chief_mean_t0");
  if (!(std::abs(std::sin(chief_mean_t0.i)) > 1e-6)) return core::Status{core::Problem::kSingular, "i", "equatorial chief: QNS ROE undefined"}.within("chief_mean_t0");
  if (auto ok = validate_roe(roe0, "roe0"); !ok) return ok;
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok;
  if (!std::isfinite(t_earliest) || t_earliest < 0.0) return core::Status{core::Problem::kOutOfRange, "t_earliest", "must be finite and >= 0"};
  if (!std::isfinite(tf) || !(tf > t_earliest)) return core::Status{core::Problem::kOutOfRange, "tf", "must be finite and > t_earliest"};
  const double a = chief_mean_t0.a;
  const double period = 2.0 * std::numbers::pi / std::sqrt(settings_.gravity.mu / (a * a * a));
  if (tf - t_earliest < settings_.min_horizon_orbits * period) {
    return core::Status{core::Problem::kOutOfRange, "horizon", "tf - t_earliest is below min_horizon_orbits"};
  }
  return {};
}

// Step 1: B_k on the grid, the anchors and the initial dynamic slots (between the anchors).
void ReachableSetPlanner::build_grid(Problem& pb, double t_earliest) {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  const int ng = s.grid_points;
  pb.dt = (pb.tf - t_earliest) / static_cast<double>(ng - 1);
  for (int k = 0; k < ng; ++k) {
    const double t = (k == ng - 1) ? pb.tf : t_earliest + pb.dt * static_cast<double>(k);
    w.t_grid[at(k)] = t;
    w.b_grid[at(k)] = pb.n * pb.chief->a * impulse_effect(*pb.chief, t, pb.tf, s.gravity);
  }
  const int na = s.anchor_points;
  for (int j = 0; j < na; ++j) {
    w.anchors[at(j)] = static_cast<int>(std::lround(static_cast<double>(j) * (ng - 1) / static_cast<double>(na - 1)));
  }
  const int dyn = s.working_set_size - na;
  w.slots.clear();
  for (int j = 0; j < dyn; ++j) w.slots.push_back(static_cast<int>(std::lround((j + 0.5) * (ng - 1) / static_cast<double>(dyn))));
}

// Reachability screen by weak duality (docs/algorithms/control.md#delta-v-lower-bounds): for any
// lambda, the cost is at least lambda'w / max_k ||B_k' lambda||. Along the eigenvectors of the
// grid Gramian sum_k B_k B_k' of the smallest eigenvalues this bound is large exactly when the
// window cannot steer some direction of w cheaply; beyond the dual box, the target counts as
// unreachable (and the restricted SOCPs would be too ill-conditioned to say so themselves).
core::Status ReachableSetPlanner::screen_reachability(const Problem& pb) const {
  const ReachableSetSettings& s = settings_;
  const Workspace& w = *work_;
  const int ng = s.grid_points;
  Eigen::Matrix<double, 6, 6> gramian = Eigen::Matrix<double, 6, 6>::Zero();
  for (int k = 0; k < ng; ++k) gramian += w.b_grid[at(k)] * w.b_grid[at(k)].transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> gram_eig(gramian);
  for (int r = 0; r < 6; ++r) {
    const Vector6 v = gram_eig.eigenvectors().col(r);
    double support = 0.0;
    for (int k = 0; k < ng; ++k) support = std::max(support, (w.b_grid[at(k)].transpose() * v).norm());
    if (std::abs(pb.w_hat.dot(v)) > 0.5 * s.dual_box * support) {
      return core::Status{core::Problem::kInfeasible, "roe_target", "unreachable in the window: the dual lower bound exceeds the dual box"};
    }
  }
  return {};
}

// Step 2: exchange iteration on the restricted dual (KD21), until no grid constraint
// is violated by more than dual_tolerance. Leaves lambda, h_grid and h_max in the workspace.
core::Status ReachableSetPlanner::exchange_iteration(const Problem& pb) {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  const int ng = s.grid_points;
  const int na = s.anchor_points;
  optim::ConicProblem& dp = w.dual_problem;
  dp.c = -pb.w_hat;
  w.lambda.setZero();
  w.h_max = 0.0;
  for (int it = 0; it < s.max_exchange_iterations; ++it) {
    for (int j = 0; j < s.working_set_size; ++j) {
      dp.G.block(12 + 4 * j + 1, 0, 3, 6) = -w.b_grid[at(w.slot_grid_index(j, na))].transpose();
    }
    const auto info = w.dual_solver.solve(dp);
    if (!info.ok()) return info.status().within("solver");
    stats_.socp_iterations += info->iterations;
    stats_.exchange_iterations = it + 1;
    if (info->status == optim::ConicStatus::kPrimalInfeasible || info->status == optim::ConicStatus::kDualInfeasible) {
      return core::Status{core::Problem::kInfeasible, "roe_target", "restricted dual SOCP infeasible"};
    }
    if (!usable(info->status)) {
      return core::Status{core::Problem::kNotConverged, "solver", "restricted dual SOCP not solved"};
    }
    w.lambda = w.dual_solver.x();
    if (!w.lambda.allFinite()) return core::Status{core::Problem::kNotFinite, "solver", "restricted dual SOCP returned a non-finite multiplier"};
    if (w.lambda.cwiseAbs().maxCoeff() > 0.5 * s.dual_box) {
      return core::Status{core::Problem::kInfeasible, "roe_target", "unreachable in the window: the dual box binds"};
    }
    w.h_max = 0.0;
    for (int k = 0; k < ng; ++k) {
      const double hk = (w.b_grid[at(k)].transpose() * w.lambda).norm();
      w.h_grid[at(k)] = hk;
      w.h_max = std::max(w.h_max, hk);
    }
    stats_.max_dual_violation = w.h_max - 1.0;
    stats_.grid_dual_objective = pb.w_hat.dot(w.lambda) * pb.dv_scale;
    if (w.h_max <= 1.0 + s.dual_tolerance) break;
    update_working_set();
  }
  return {};
}

bool ReachableSetPlanner::is_local_max(int k) const {
  const auto& h = work_->h_grid;
  const int ng = settings_.grid_points;
  return (k == 0 || h[at(k)] >= h[at(k - 1)]) && (k == ng - 1 || h[at(k)] >= h[at(k + 1)]);
}

// New dynamic slots: the still-active ones, then the violated peaks (largest first), then the
// previous slots as padding (valid constraints of the grid problem, so harmless).
void ReachableSetPlanner::update_working_set() {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  const int dyn = s.working_set_size - s.anchor_points;
  auto used = [&](int k) {
    return std::find(w.next_slots.begin(), w.next_slots.end(), k) != w.next_slots.end() ||
           std::find(w.anchors.begin(), w.anchors.end(), k) != w.anchors.end();
  };
  auto full = [&] { return static_cast<int>(w.next_slots.size()) >= dyn; };
  w.next_slots.clear();
  for (int k : w.slots) {
    if (!full() && w.h_grid[at(k)] >= 1.0 - s.contact_tolerance && !used(k)) w.next_slots.push_back(k);
  }
  w.peaks.clear();
  for (int k = 0; k < s.grid_points; ++k) {
    if (w.h_grid[at(k)] > 1.0 + s.dual_tolerance && is_local_max(k)) w.peaks.push_back(k);
  }
  std::sort(w.peaks.begin(), w.peaks.end(), [&](int l, int r) { return w.h_grid[at(l)] > w.h_grid[at(r)]; });
  for (int k : w.peaks) {
    if (full()) break;
    if (!used(k)) w.next_slots.push_back(k);
  }
  for (int k : w.slots) {
    if (full()) break;
    if (std::find(w.next_slots.begin(), w.next_slots.end(), k) == w.next_slots.end()) w.next_slots.push_back(k);
  }
  while (!full()) w.next_slots.push_back(w.anchors[0]);
  std::swap(w.slots, w.next_slots);
}

void ReachableSetPlanner::add_candidate(double t, const Effect& b) {
  Workspace& w = *work_;
  for (int j = 0; j < w.count; ++j) {
    if (std::abs(w.cand_t[at(j)] - t) <= 1e-9 * (1.0 + std::abs(t))) return;
  }
  if (w.count >= settings_.max_candidates) return;
  w.cand_t[at(w.count)] = t;
  w.cand_b[at(w.count)] = b;
  ++w.count;
}

// Step 3: candidate times. (i) The support of the restricted primal: the working-set constraints
// whose cone multipliers carry impulse (dv_k = -z_k(1:3)); adjacent grid points can both carry
// impulse when the continuous optimum has two distinct burns closer than a grid step, which the
// peaks alone would merge. (ii) The peaks of h within contact_tolerance of the maximum, refined
// off the grid by the parabola through their three grid values. The magnitude SOCP over both
// is never worse than the grid optimum and usually a little better.
void ReachableSetPlanner::collect_candidates(const Problem& pb) {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  const int ng = s.grid_points;
  w.count = 0;
  const Eigen::VectorXd& z = w.dual_solver.z();
  double z_sum = 0.0;
  for (int j = 0; j < s.working_set_size; ++j) z_sum += std::max(0.0, z(12 + 4 * j));
  w.peaks.clear();
  for (int j = 0; j < s.working_set_size; ++j) {
    if (z(12 + 4 * j) > 1e-4 * z_sum) w.peaks.push_back(j);
  }
  std::sort(w.peaks.begin(), w.peaks.end(), [&](int l, int r) { return z(12 + 4 * l) > z(12 + 4 * r); });
  for (int j : w.peaks) {
    const int k = w.slot_grid_index(j, s.anchor_points);
    add_candidate(w.t_grid[at(k)], w.b_grid[at(k)]);
  }
  w.peaks.clear();
  for (int k = 0; k < ng; ++k) {
    if (w.h_grid[at(k)] >= (1.0 - s.contact_tolerance) * w.h_max && is_local_max(k)) w.peaks.push_back(k);
  }
  std::sort(w.peaks.begin(), w.peaks.end(), [&](int l, int r) { return w.h_grid[at(l)] > w.h_grid[at(r)]; });
  for (int k : w.peaks) {
    const double hm = k > 0 ? w.h_grid[at(k - 1)] : 0.0;
    const double h0 = w.h_grid[at(k)];
    const double hp = k < ng - 1 ? w.h_grid[at(k + 1)] : 0.0;
    const double curvature = hm - 2.0 * h0 + hp;
    if (k == 0 || k == ng - 1 || !(curvature < 0.0)) {
      add_candidate(w.t_grid[at(k)], w.b_grid[at(k)]);
      continue;
    }
    // Parabola through (k-1, k, k+1): vertex offset in grid steps.
    const double t = w.t_grid[at(k)] + std::clamp(0.5 * (hm - hp) / curvature, -0.5, 0.5) * pb.dt;
    add_candidate(t, pb.n * pb.chief->a * impulse_effect(*pb.chief, t, pb.tf, s.gravity));
  }
}

// min sum ||dv_j|| s.t. sum B_j dv_j = w_hat over the first m candidates' times, with candidate
// `skip` left out (-1: none); the impulses go to `dv_out` (m or m - 1 of them, in order).
core::Outcome<double> ReachableSetPlanner::solve_fixed_times(const Problem& pb, int m, int skip,
                                                            std::vector<Eigen::Vector3d>& dv_out) {
  Workspace& w = *work_;
  const int used = skip >= 0 ? m - 1 : m;
  optim::ConicProblem& pp = w.primal_problems[at(used - 1)];
  optim::ConicSolver& ps = w.primal_solvers[at(used - 1)];
  for (int j = 0, col = 0; j < m; ++j) {
    if (j == skip) continue;
    pp.A.block(0, 3 * col++, 6, 3) = w.cand_b[at(j)];
  }
  pp.b = pb.w_hat;
  const auto info = ps.solve(pp);
  if (!info.ok()) return info.status().within("solver");
  stats_.socp_iterations += info->iterations;
  if (!usable(info->status)) {
    return core::Status{core::Problem::kNotConverged, "solver", "magnitude SOCP not solved"};
  }
  double sum_norm = 0.0;
  for (int j = 0; j < used; ++j) {
    dv_out[at(j)] = ps.x().segment<3>(3 * j);
    sum_norm += dv_out[at(j)].norm();
  }
  if (!std::isfinite(sum_norm)) return core::Status{core::Problem::kNotFinite, "solver", "magnitude SOCP returned a non-finite solution"};
  return sum_norm;
}

// Step 4a: magnitudes, min sum ||dv_j|| over all the contact times; interior-point iterates leave
// ~tolerance-sized impulses at unused times, which are dropped.
core::Status ReachableSetPlanner::solve_magnitudes(const Problem& pb) {
  Workspace& w = *work_;
  const auto sum_norm = solve_fixed_times(pb, w.count, -1, w.cand_dv);
  if (!sum_norm.ok()) return sum_norm.status();
  for (int j = w.count - 1; j >= 0; --j) {
    if (w.cand_dv[at(j)].norm() <= 1e-6 * *sum_norm) w.remove_candidate(j);
  }
  return {};
}

// Step 4b: Caratheodory reduction to at most 6 impulses: with the directions fixed, the cost is
// linear in the impulse scales alpha_j, and 7 effects B_j dv_j in R^6 are dependent; moving alpha
// along the null vector (the direction that does not raise the cost; at the optimum the cost is
// flat along it) until one scale reaches 0 removes an impulse without changing the terminal state.
// Only valid while 7 or more impulses remain: 6 generic effects in R^6 are independent.
void ReachableSetPlanner::reduce_to_six() {
  Workspace& w = *work_;
  while (w.count > 6) {
    Eigen::Matrix<double, 6, 7> v;
    Eigen::Matrix<double, 7, 1> cost;
    for (int j = 0; j < 7; ++j) {
      v.col(j) = w.cand_b[at(j)] * w.cand_dv[at(j)];
      cost(j) = w.cand_dv[at(j)].norm();
    }
    // Null vector of v: the eigenvector of v'v (7x7, rank <= 6) of the smallest eigenvalue.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 7, 7>> null_eig(v.transpose() * v);
    Eigen::Matrix<double, 7, 1> nu = null_eig.eigenvectors().col(0);
    if (nu.dot(cost) < 0.0) nu = -nu;  // alpha = 1 - step nu then does not raise the cost
    if (nu.maxCoeff() <= 0.0) nu = -nu;
    double step = std::numeric_limits<double>::infinity();
    int drop = 0;
    for (int j = 0; j < 7; ++j) {
      if (nu(j) > 0.0 && 1.0 / nu(j) < step) {
        step = 1.0 / nu(j);
        drop = j;
      }
    }
    for (int j = 0; j < 7; ++j) w.cand_dv[at(j)] *= std::max(0.0, 1.0 - step * nu(j));
    w.remove_candidate(drop);
  }
}

// Step 4c (max_impulses < 6 only): a cardinality constraint, which the convex problem does not
// have. One impulse: the best least-squares impulse over the grid, accepted only if it reaches the
// target (a general 6-element change needs two). Two: every pair of grid times, each a 6x6 linear
// system with a unique solution (exhaustive, (ng^2 - ng)/2 solves). Three to five: greedy
// elimination from the optimal support (drop the impulse whose removal costs least, re-solving the
// magnitude SOCP over the remaining times), kept only when cheaper than the best pair (which is
// also a feasible k-impulse plan).
core::Status ReachableSetPlanner::reduce_to_max_impulses(const Problem& pb) {
  const int k = settings_.max_impulses;
  if (k == 1) return best_single_impulse(pb);
  Workspace& w = *work_;
  double greedy_cost = std::numeric_limits<double>::infinity();
  if (k >= 3) {
    while (w.count > k) {
      int best = -1;
      double best_cost = std::numeric_limits<double>::infinity();
      for (int j = 0; j < w.count; ++j) {
        const auto cost = solve_fixed_times(pb, w.count, j, w.trial_dv);
        if (!cost.ok() || !(*cost < best_cost)) continue;  // this subset cannot reach the target
        best_cost = *cost;
        best = j;
        std::copy_n(w.trial_dv.begin(), w.count - 1, w.best_dv.begin());
      }
      if (best < 0) break;
      w.remove_candidate(best);
      std::copy_n(w.best_dv.begin(), w.count, w.cand_dv.begin());
      greedy_cost = best_cost;
    }
    if (w.count > k) greedy_cost = std::numeric_limits<double>::infinity();
  }
  return best_impulse_pair(pb, greedy_cost);
}

core::Status ReachableSetPlanner::best_single_impulse(const Problem& pb) {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  double best_miss = std::numeric_limits<double>::infinity();
  int best = -1;
  Eigen::Vector3d best_dv = Eigen::Vector3d::Zero();
  for (int g = 0; g < s.grid_points; ++g) {
    const Effect& b = w.b_grid[at(g)];
    const Eigen::Vector3d dv = (b.transpose() * b).ldlt().solve(b.transpose() * pb.w_hat);
    const double miss = (b * dv - pb.w_hat).norm() * pb.w_norm;
    if (miss < best_miss) {
      best_miss = miss;
      best = g;
      best_dv = dv;
    }
  }
  if (best < 0 || !(best_miss <= s.terminal_tolerance_m)) {
    return core::Status{core::Problem::kInfeasible, "max_impulses",
                        "one impulse cannot reach this change (a general 6-element change needs two)"};
  }
  w.count = 1;
  w.cand_t[0] = w.t_grid[at(best)];
  w.cand_b[0] = w.b_grid[at(best)];
  w.cand_dv[0] = best_dv;
  return {};
}

core::Status ReachableSetPlanner::best_impulse_pair(const Problem& pb, double cost_to_beat) {
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  double best_cost = cost_to_beat;
  int best_p = -1, best_q = -1;
  Vector6 best_x = Vector6::Zero();
  Eigen::Matrix<double, 6, 6> pair;
  for (int p = 0; p < s.grid_points; ++p) {
    pair.leftCols<3>() = w.b_grid[at(p)];
    for (int q = p + 1; q < s.grid_points; ++q) {
      pair.rightCols<3>() = w.b_grid[at(q)];
      const Eigen::PartialPivLU<Eigen::Matrix<double, 6, 6>> lu(pair);
      const Vector6 x = lu.solve(pb.w_hat);
      // A (nearly) singular pair cannot reach every direction: its solution does not satisfy the
      // system to round-off.
      if (!x.allFinite() || (pair * x - pb.w_hat).norm() > 1e-9) continue;
      const double cost = x.head<3>().norm() + x.tail<3>().norm();
      if (cost < best_cost) {
        best_cost = cost;
        best_p = p;
        best_q = q;
        best_x = x;
      }
    }
  }
  if (best_p < 0) {
    if (std::isfinite(cost_to_beat)) return {};  // the greedy plan stands
    return core::Status{core::Problem::kInfeasible, "max_impulses", "no plan with max_impulses impulses reaches the target"};
  }
  w.count = 2;
  w.cand_t[0] = w.t_grid[at(best_p)];
  w.cand_b[0] = w.b_grid[at(best_p)];
  w.cand_dv[0] = best_x.head<3>();
  w.cand_t[1] = w.t_grid[at(best_q)];
  w.cand_b[1] = w.b_grid[at(best_q)];
  w.cand_dv[1] = best_x.tail<3>();
  return {};
}

// Step 4d: minimum-norm correction of the remaining equality residual (in the range of [B_j]):
// the SOCP meets its equality only to its tolerance.
void ReachableSetPlanner::correct_terminal_residual(const Problem& pb) {
  Workspace& w = *work_;
  Vector6 residual = pb.w_hat;
  Eigen::Matrix<double, 6, 6> gram = Eigen::Matrix<double, 6, 6>::Zero();
  for (int j = 0; j < w.count; ++j) {
    const Effect& bj = w.cand_b[at(j)];
    residual -= bj * w.cand_dv[at(j)];
    gram += bj * bj.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(gram);
  const double eig_max = eig.eigenvalues().maxCoeff();
  Vector6 coeff = eig.eigenvectors().transpose() * residual;
  for (int r = 0; r < 6; ++r) {
    const double ev = eig.eigenvalues()(r);
    coeff(r) = ev > 1e-12 * eig_max ? coeff(r) / ev : 0.0;
  }
  const Vector6 y = eig.eigenvectors() * coeff;
  for (int j = 0; j < w.count; ++j) w.cand_dv[at(j)] += w.cand_b[at(j)].transpose() * y;
}

// Step 5: the plan, in m/s, sorted by time; never ok with a terminal miss (an always-on check of
// the linear model's terminal state against the target).
core::Status ReachableSetPlanner::emit_plan(const Problem& pb, const astro::RelativeOrbitalElements& drift,
                                                  ManeuverPlan& result) const {
  const Workspace& w = *work_;
  Vector6 reached = Vector6::Zero();
  for (int j = 0; j < w.count; ++j) {
    const Eigen::Vector3d dv = w.cand_dv[at(j)] * pb.dv_scale;
    reached += w.cand_b[at(j)] * w.cand_dv[at(j)];
    result.impulses.push_back(Impulse{w.cand_t[at(j)], dv});
  }
  std::sort(result.impulses.begin(), result.impulses.end(), [](const Impulse& l, const Impulse& r) { return l.t < r.t; });
  result.dv_total_mps = total_delta_v(result.impulses);
  if (!std::isfinite(result.dv_total_mps)) return core::Status{core::Problem::kNotFinite, "solver", "non-finite plan"};
  const double miss_m = (reached - pb.w_hat).norm() * pb.w_norm;
  if (!(miss_m <= settings_.terminal_tolerance_m)) {
    return core::Status{core::Problem::kNotConverged, "solver", "the plan misses the target in the linear model"};
  }
  result.roe_final_predicted = drift + reached * (pb.w_norm / pb.chief->a);
  return {};
}

}  // namespace visors::control
