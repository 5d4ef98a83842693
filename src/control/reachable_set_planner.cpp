#include "control/reachable_set_planner.hpp"
#include "control/impulse_effect.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <Eigen/Dense>

#include "astro/control_input_matrix.hpp"
#include "astro/j2_secular.hpp"
#include "astro/roe_stm.hpp"
#include "optim/conic_problem.hpp"
#include "optim/conic_solver.hpp"

namespace visors::control {
namespace {

using Effect = Eigen::Matrix<double, 6, 3>;

core::Error invalid(std::string field, std::string message) {
  return core::Error{std::move(field), std::move(message)};
}

// Restricted dual (digest sec. 5.4(a)), variables lambda (6): min -w'lambda s.t.
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

// Magnitude SOCP over m fixed times (digest sec. 5.4(b)): variables [dv_1..dv_m, s_1..s_m],
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

}  // namespace

struct ReachableSetPlanner::Workspace {
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
  std::vector<double> cand_t;
  std::vector<Effect> cand_b;
  std::vector<Eigen::Vector3d> cand_dv;

  Workspace(optim::ConicSolver dual, optim::ConicProblem dual_pr)
      : dual_solver(std::move(dual)), dual_problem(std::move(dual_pr)) {}
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
  if (!(s.gravity.mu > 0.0 && s.gravity.re > 0.0 && std::isfinite(s.gravity.j2))) {
    return invalid("gravity", "mu and re must be > 0, j2 finite");
  }

  const int slots = s.working_set_size;
  auto dual = optim::ConicSolver::create(dual_dimensions(slots), s.solver);
  if (!dual.ok()) return invalid("solver", dual.error().describe());
  optim::ConicProblem dpr;
  const int rows = 12 + 4 * slots;
  dpr.c = Eigen::VectorXd::Zero(6);
  dpr.G = Eigen::MatrixXd::Zero(rows, 6);
  dpr.G.topRows(6) = Eigen::MatrixXd::Identity(6, 6);
  dpr.G.middleRows(6, 6) = -Eigen::MatrixXd::Identity(6, 6);
  dpr.h = Eigen::VectorXd::Zero(rows);
  dpr.h.head(12).setConstant(s.dual_box);
  for (int k = 0; k < slots; ++k) dpr.h(12 + 4 * k) = 1.0;
  dpr.A.resize(0, 6);
  dpr.b.resize(0);

  ReachableSetPlanner planner(s);
  planner.work_ = std::make_unique<Workspace>(std::move(dual).value(), std::move(dpr));
  Workspace& w = *planner.work_;
  const auto grid = static_cast<std::size_t>(s.grid_points);
  w.t_grid.assign(grid, 0.0);
  w.b_grid.assign(grid, Effect::Zero());
  w.h_grid.assign(grid, 0.0);
  w.peaks.reserve(grid);
  w.anchors.assign(static_cast<std::size_t>(s.anchor_points), 0);
  w.slots.reserve(static_cast<std::size_t>(slots));
  w.next_slots.reserve(static_cast<std::size_t>(slots));
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

core::Result<bool> ReachableSetPlanner::plan_into(ManeuverPlan& result, const astro::KeplerianElements& chief_mean_t0,
                                                  const astro::RelativeOrbitalElements& roe0,
                                                  const astro::RelativeOrbitalElements& roe_target, double t_earliest,
                                                  double tf) {
  result.impulses.clear();
  result.dv_total = 0.0;
  result.dv_lower_bound = 0.0;
  const ReachableSetSettings& s = settings_;
  Workspace& w = *work_;
  stats_ = ReachableSetStats{};

  // ---- Input checks.
  const auto chief_ok = astro::validate_keplerian(chief_mean_t0);
  if (!chief_ok.ok()) return invalid("chief_mean_t0." + chief_ok.error().field, chief_ok.error().message);
  const double sin_i = std::sin(chief_mean_t0.i);
  if (!(std::abs(sin_i) > 1e-6)) return invalid("chief_mean_t0.i", "equatorial chief: QNS ROE undefined");
  if (auto ok = validate_roe(roe0, "roe0"); !ok) return ok.error();
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok.error();
  if (!std::isfinite(t_earliest) || t_earliest < 0.0) return invalid("t_earliest", "must be finite and >= 0");
  if (!std::isfinite(tf) || !(tf > t_earliest)) return invalid("tf", "must be finite and > t_earliest");
  const double a = chief_mean_t0.a;
  const double n = std::sqrt(s.gravity.mu / (a * a * a));
  const double period = 2.0 * std::numbers::pi / n;
  if (tf - t_earliest < s.min_horizon_orbits * period) {
    return invalid("horizon", "tf - t_earliest = " + std::to_string(tf - t_earliest) + " s is below min_horizon_orbits");
  }

  // ---- Pseudostate in metres, normalised.
  const astro::RoeStm phi_f0 = astro::j2_roe_stm(chief_mean_t0, tf, s.gravity);
  const astro::RelativeOrbitalElements drift = phi_f0 * roe0;
  const Eigen::Matrix<double, 6, 1> w_m = a * (roe_target - drift);
  const double w_norm = w_m.norm();
  result.roe_final_predicted = drift;
  if (!std::isfinite(w_norm)) return invalid("roe_target", "pseudostate is not finite");
  if (w_norm <= 1e-12 * a * std::max(roe_target.norm(), 1e-9)) return true;  // already on target
  const Eigen::Matrix<double, 6, 1> w_hat = w_m / w_norm;
  // dv [m/s] = (scaled dv) * n * |a w|: sum (n B_k)(dv_k / (n |a w|)) = a w / |a w|.
  const double dv_scale = n * w_norm;

  // ---- Grid.
  const int ng = s.grid_points;
  const double dt = (tf - t_earliest) / static_cast<double>(ng - 1);
  for (int k = 0; k < ng; ++k) {
    const double t = (k == ng - 1) ? tf : t_earliest + dt * static_cast<double>(k);
    w.t_grid[static_cast<std::size_t>(k)] = t;
    w.b_grid[static_cast<std::size_t>(k)] = n * chief_mean_t0.a * impulse_effect(chief_mean_t0, t, tf, s.gravity);
  }
  const int na = s.anchor_points;
  for (int j = 0; j < na; ++j) {
    w.anchors[static_cast<std::size_t>(j)] =
        static_cast<int>(std::lround(static_cast<double>(j) * (ng - 1) / static_cast<double>(na - 1)));
  }
  const int dyn = s.working_set_size - na;
  w.slots.clear();
  for (int j = 0; j < dyn; ++j) {  // start between the anchors
    w.slots.push_back(static_cast<int>(std::lround((j + 0.5) * (ng - 1) / static_cast<double>(dyn))));
  }

  // Reachability screen by weak duality (digest sec. 4.2): for any lambda, the cost is at least
  // lambda'w / max_k ||B_k' lambda||. Along the eigenvectors of the grid Gramian sum_k B_k B_k'
  // of the smallest eigenvalues this bound is large exactly when the window cannot steer some
  // direction of w cheaply; beyond the dual box, the target counts as unreachable (and the
  // restricted SOCPs would be too ill-conditioned to say so themselves).
  {
    Eigen::Matrix<double, 6, 6> gramian = Eigen::Matrix<double, 6, 6>::Zero();
    for (int k = 0; k < ng; ++k) gramian += w.b_grid[static_cast<std::size_t>(k)] * w.b_grid[static_cast<std::size_t>(k)].transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> gram_eig(gramian);
    for (int r = 0; r < 6; ++r) {
      const Eigen::Matrix<double, 6, 1> v = gram_eig.eigenvectors().col(r);
      double support = 0.0;
      for (int k = 0; k < ng; ++k) support = std::max(support, (w.b_grid[static_cast<std::size_t>(k)].transpose() * v).norm());
      if (std::abs(w_hat.dot(v)) > 0.5 * s.dual_box * support) {
        return invalid("roe_target", "unreachable in the window: the dual lower bound exceeds " +
                                         std::to_string(0.5 * s.dual_box * dv_scale) + " m/s");
      }
    }
  }

  auto grid_index_used = [&](const std::vector<int>& list, int k) {
    return std::find(list.begin(), list.end(), k) != list.end() ||
           std::find(w.anchors.begin(), w.anchors.end(), k) != w.anchors.end();
  };
  auto local_max = [&](int k) {
    const auto& h = w.h_grid;
    const auto ku = static_cast<std::size_t>(k);
    return (k == 0 || h[ku] >= h[ku - 1]) && (k == ng - 1 || h[ku] >= h[ku + 1]);
  };

  // ---- Exchange iteration on the restricted dual.
  optim::ConicProblem& dp = w.dual_problem;
  dp.c = -w_hat;
  Eigen::Matrix<double, 6, 1> lambda = Eigen::Matrix<double, 6, 1>::Zero();
  double h_max = 0.0;
  for (int it = 0; it < s.max_exchange_iterations; ++it) {
    for (int j = 0; j < s.working_set_size; ++j) {
      const int k = j < na ? w.anchors[static_cast<std::size_t>(j)] : w.slots[static_cast<std::size_t>(j - na)];
      dp.G.block(12 + 4 * j + 1, 0, 3, 6) = -w.b_grid[static_cast<std::size_t>(k)].transpose();
    }
    const auto info = w.dual_solver.solve(dp);
    if (!info.ok()) return invalid("solver", info.error().describe());
    stats_.socp_iterations += info->iterations;
    stats_.exchange_iterations = it + 1;
    if (info->status == optim::ConicStatus::primal_infeasible || info->status == optim::ConicStatus::dual_infeasible) {
      return invalid("roe_target", std::string("restricted dual SOCP is ") + std::string(optim::to_string(info->status)));
    }
    if (info->status != optim::ConicStatus::optimal && info->status != optim::ConicStatus::max_iterations) {
      return invalid("solver", std::string("restricted dual SOCP: ") + std::string(optim::to_string(info->status)));
    }
    lambda = w.dual_solver.x();
    if (!lambda.allFinite()) return invalid("solver", "restricted dual SOCP returned a non-finite multiplier");
    if (lambda.cwiseAbs().maxCoeff() > 0.5 * s.dual_box) {
      return invalid("roe_target", "unreachable in the window: the dual box binds (cost above ~" +
                                       std::to_string(0.5 * s.dual_box * dv_scale) + " m/s)");
    }
    h_max = 0.0;
    for (int k = 0; k < ng; ++k) {
      const double hk = (w.b_grid[static_cast<std::size_t>(k)].transpose() * lambda).norm();
      w.h_grid[static_cast<std::size_t>(k)] = hk;
      h_max = std::max(h_max, hk);
    }
    stats_.max_dual_violation = h_max - 1.0;
    stats_.grid_dual_objective = w_hat.dot(lambda) * dv_scale;
    if (h_max <= 1.0 + s.dual_tolerance) break;

    // New dynamic slots: the still-active ones, then the violated peaks (largest first), then the
    // previous slots as padding (valid constraints of the grid problem, so harmless).
    w.next_slots.clear();
    for (int k : w.slots) {
      if (static_cast<int>(w.next_slots.size()) < dyn && w.h_grid[static_cast<std::size_t>(k)] >= 1.0 - s.contact_tolerance &&
          !grid_index_used(w.next_slots, k)) {
        w.next_slots.push_back(k);
      }
    }
    w.peaks.clear();
    for (int k = 0; k < ng; ++k) {
      if (w.h_grid[static_cast<std::size_t>(k)] > 1.0 + s.dual_tolerance && local_max(k)) w.peaks.push_back(k);
    }
    std::sort(w.peaks.begin(), w.peaks.end(),
              [&](int l, int r) { return w.h_grid[static_cast<std::size_t>(l)] > w.h_grid[static_cast<std::size_t>(r)]; });
    for (int k : w.peaks) {
      if (static_cast<int>(w.next_slots.size()) >= dyn) break;
      if (!grid_index_used(w.next_slots, k)) w.next_slots.push_back(k);
    }
    for (int k : w.slots) {
      if (static_cast<int>(w.next_slots.size()) >= dyn) break;
      if (std::find(w.next_slots.begin(), w.next_slots.end(), k) == w.next_slots.end()) w.next_slots.push_back(k);
    }
    while (static_cast<int>(w.next_slots.size()) < dyn) w.next_slots.push_back(w.anchors[0]);
    std::swap(w.slots, w.next_slots);
  }
  // lambda / h_max is feasible for every grid constraint: weak duality gives the bound.
  result.dv_lower_bound = std::max(0.0, w_hat.dot(lambda) / h_max) * dv_scale;

  // ---- Candidate times. (i) The support of the restricted primal: the working-set constraints
  // whose cone multipliers carry impulse (dv_k = -z_k(1:3)); adjacent grid points can both carry
  // impulse when the continuous optimum has two distinct burns closer than a grid step, which the
  // peaks alone would merge. (ii) The peaks of h within contact_tolerance of the maximum, refined
  // off the grid by the parabola through their three grid values. The magnitude SOCP over both
  // is never worse than the grid optimum and usually a little better.
  int m = 0;
  auto add_candidate = [&](double t, const Effect& b) {
    for (int j = 0; j < m; ++j) {
      if (std::abs(w.cand_t[static_cast<std::size_t>(j)] - t) <= 1e-9 * (1.0 + std::abs(t))) return;
    }
    if (m >= s.max_candidates) return;
    w.cand_t[static_cast<std::size_t>(m)] = t;
    w.cand_b[static_cast<std::size_t>(m)] = b;
    ++m;
  };
  {
    const Eigen::VectorXd& z = w.dual_solver.z();
    double z_sum = 0.0;
    for (int j = 0; j < s.working_set_size; ++j) z_sum += std::max(0.0, z(12 + 4 * j));
    w.peaks.clear();
    for (int j = 0; j < s.working_set_size; ++j) {
      if (z(12 + 4 * j) > 1e-4 * z_sum) w.peaks.push_back(j);
    }
    std::sort(w.peaks.begin(), w.peaks.end(), [&](int l, int r) { return z(12 + 4 * l) > z(12 + 4 * r); });
    for (int j : w.peaks) {
      const int k = j < na ? w.anchors[static_cast<std::size_t>(j)] : w.slots[static_cast<std::size_t>(j - na)];
      add_candidate(w.t_grid[static_cast<std::size_t>(k)], w.b_grid[static_cast<std::size_t>(k)]);
    }
  }
  w.peaks.clear();
  for (int k = 0; k < ng; ++k) {
    if (w.h_grid[static_cast<std::size_t>(k)] >= (1.0 - s.contact_tolerance) * h_max && local_max(k)) w.peaks.push_back(k);
  }
  std::sort(w.peaks.begin(), w.peaks.end(),
            [&](int l, int r) { return w.h_grid[static_cast<std::size_t>(l)] > w.h_grid[static_cast<std::size_t>(r)]; });
  for (int k : w.peaks) {
    const auto ku = static_cast<std::size_t>(k);
    if (k == 0 || k == ng - 1) {
      add_candidate(w.t_grid[ku], w.b_grid[ku]);
      continue;
    }
    // Parabola through (k-1, k, k+1): vertex offset in grid steps.
    const double hm = w.h_grid[ku - 1], h0 = w.h_grid[ku], hp = w.h_grid[ku + 1];
    const double curvature = hm - 2.0 * h0 + hp;
    if (!(curvature < 0.0)) {
      add_candidate(w.t_grid[ku], w.b_grid[ku]);
      continue;
    }
    const double t = w.t_grid[ku] + std::clamp(0.5 * (hm - hp) / curvature, -0.5, 0.5) * dt;
    add_candidate(t, n * chief_mean_t0.a * impulse_effect(chief_mean_t0, t, tf, s.gravity));
  }
  if (m == 0) return invalid("solver", "no contact time found");
  stats_.candidates = m;

  // ---- Magnitudes: min sum ||dv_j|| over the contact times.
  optim::ConicProblem& pp = w.primal_problems[static_cast<std::size_t>(m - 1)];
  optim::ConicSolver& ps = w.primal_solvers[static_cast<std::size_t>(m - 1)];
  for (int j = 0; j < m; ++j) pp.A.block(0, 3 * j, 6, 3) = w.cand_b[static_cast<std::size_t>(j)];
  pp.b = w_hat;
  const auto pinfo = ps.solve(pp);
  if (!pinfo.ok()) return invalid("solver", pinfo.error().describe());
  stats_.socp_iterations += pinfo->iterations;
  if (pinfo->status != optim::ConicStatus::optimal && pinfo->status != optim::ConicStatus::max_iterations) {
    return invalid("solver", std::string("magnitude SOCP: ") + std::string(optim::to_string(pinfo->status)));
  }
  int count = m;
  double sum_norm = 0.0;
  for (int j = 0; j < m; ++j) {
    w.cand_dv[static_cast<std::size_t>(j)] = ps.x().segment<3>(3 * j);
    sum_norm += w.cand_dv[static_cast<std::size_t>(j)].norm();
  }
  if (!std::isfinite(sum_norm)) return invalid("solver", "magnitude SOCP returned a non-finite solution");
  auto remove_at = [&](int j) {
    for (int r = j; r + 1 < count; ++r) {
      w.cand_t[static_cast<std::size_t>(r)] = w.cand_t[static_cast<std::size_t>(r + 1)];
      w.cand_b[static_cast<std::size_t>(r)] = w.cand_b[static_cast<std::size_t>(r + 1)];
      w.cand_dv[static_cast<std::size_t>(r)] = w.cand_dv[static_cast<std::size_t>(r + 1)];
    }
    --count;
  };
  // Interior-point iterates leave ~tolerance-sized impulses at unused times.
  for (int j = count - 1; j >= 0; --j) {
    if (w.cand_dv[static_cast<std::size_t>(j)].norm() <= 1e-6 * sum_norm) remove_at(j);
  }
  // Caratheodory reduction: with the directions fixed, the cost is linear in the impulse scales
  // alpha_j, and 7 effects B_j dv_j in R^6 are dependent; moving alpha along the null vector
  // (the direction that does not raise the cost; at the optimum the cost is flat along it)
  // until one scale reaches 0 removes an impulse without changing the terminal state.
  while (count > s.max_impulses) {
    Eigen::Matrix<double, 6, 7> v;
    Eigen::Matrix<double, 7, 1> cost;
    for (int j = 0; j < 7; ++j) {
      v.col(j) = w.cand_b[static_cast<std::size_t>(j)] * w.cand_dv[static_cast<std::size_t>(j)];
      cost(j) = w.cand_dv[static_cast<std::size_t>(j)].norm();
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
    for (int j = 0; j < 7; ++j) w.cand_dv[static_cast<std::size_t>(j)] *= std::max(0.0, 1.0 - step * nu(j));
    remove_at(drop);
  }
  // Minimum-norm correction of the remaining equality residual (in the range of [B_j]).
  Eigen::Matrix<double, 6, 1> residual = w_hat;
  Eigen::Matrix<double, 6, 6> gram = Eigen::Matrix<double, 6, 6>::Zero();
  for (int j = 0; j < count; ++j) {
    const Effect& bj = w.cand_b[static_cast<std::size_t>(j)];
    residual -= bj * w.cand_dv[static_cast<std::size_t>(j)];
    gram += bj * bj.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(gram);
  const double eig_max = eig.eigenvalues().maxCoeff();
  Eigen::Matrix<double, 6, 1> coeff = eig.eigenvectors().transpose() * residual;
  for (int r = 0; r < 6; ++r) {
    const double ev = eig.eigenvalues()(r);
    coeff(r) = ev > 1e-12 * eig_max ? coeff(r) / ev : 0.0;
  }
  const Eigen::Matrix<double, 6, 1> y = eig.eigenvectors() * coeff;
  for (int j = 0; j < count; ++j) {
    w.cand_dv[static_cast<std::size_t>(j)] += w.cand_b[static_cast<std::size_t>(j)].transpose() * y;
  }

  // ---- The plan, in m/s, sorted by time.
  Eigen::Matrix<double, 6, 1> reached = Eigen::Matrix<double, 6, 1>::Zero();
  for (int j = 0; j < count; ++j) {
    const Eigen::Vector3d dv = w.cand_dv[static_cast<std::size_t>(j)] * dv_scale;
    reached += w.cand_b[static_cast<std::size_t>(j)] * w.cand_dv[static_cast<std::size_t>(j)];
    result.impulses.push_back(Impulse{w.cand_t[static_cast<std::size_t>(j)], dv});
  }
  std::sort(result.impulses.begin(), result.impulses.end(), [](const Impulse& l, const Impulse& r) { return l.t < r.t; });
  result.dv_total = total_delta_v(result.impulses);
  if (!std::isfinite(result.dv_total)) return invalid("solver", "non-finite plan");
  result.roe_final_predicted = drift + reached * (w_norm / a);
  return true;
}

}  // namespace visors::control
