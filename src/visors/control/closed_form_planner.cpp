#include "visors/control/closed_form_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/control/delta_v_lower_bound.hpp"
#include "visors/control/impulse_effect.hpp"

namespace visors::control {
namespace {

using Matrix63 = Eigen::Matrix<double, 6, 3>;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector4d = Eigen::Vector4d;

constexpr int kMaxCandidates = 12;
constexpr int kMaxImpulses = kMaxCandidates + 2;
static_assert(static_cast<std::size_t>(kMaxImpulses) == kMaxClosedFormImpulses);

// The in-plane rows (da, dlambda, dex, dey) of a 6-vector.
Vector4d in_plane(const Vector6d& v) { return v.head<4>(); }

struct Candidate {
  double t = 0.0;
  Matrix63 b = Matrix63::Zero();  // a * B(t) [s]
};

// Secular-J2 argument-of-latitude rate u_dot = argp_dot + M_dot [rad/s].
double latitude_rate(const astro::J2SecularRates& r) { return r.argp_dot + r.M_dot; }

// Wraps an angle to [0, period).
double wrap(double x, double period) {
  const double y = std::fmod(x, period);
  return y < 0.0 ? y + period : y;
}

// Earliest time t >= t_start at which the linear phase phase0 + rate * t is congruent to `target`
// modulo `period` (rate > 0).
double next_phase_time(double phase0, double rate, double target, double period, double t_start) {
  const double phase_start = phase0 + rate * t_start;
  return t_start + wrap(target - phase_start, period) / rate;
}

// The l1-optimal tangential magnitudes over a subset of candidates (see the header, step 3).
struct Basis {
  std::array<int, 4> index{};
  int size = 0;
  Vector4d x = Vector4d::Zero();
  double score = 0.0;
};


// The planning problem once validated: the chief's secular J2 motion, the burn window [ts, te]
// and the pseudostate w = a (roe_target - Phi(tf) roe0) the impulses must produce [m].
struct ClosedFormProblem {
  const astro::KeplerianElements* chief = nullptr;
  const core::EarthGravityConstants* gravity = nullptr;
  const ClosedFormSettings* settings = nullptr;
  astro::J2SecularRates rates;
  double u_dot = 0.0;  // [rad/s]
  double orbit = 0.0;  // [s]
  double tf = 0.0, ts = 0.0, te = 0.0;  // [s since t0]
  double a = 0.0, n = 0.0, u0 = 0.0;
  Vector6d w = Vector6d::Zero();  // [m]

  /// a B(t): the mean-ROE change at tf of a unit RTN impulse at t, in metres per (m/s).
  [[nodiscard]] Matrix63 b_at(double t) const { return a * impulse_effect(*chief, t, tf, *gravity); }
};

// The impulses being built: times with their input matrices, and their delta-v [m/s, RTN].
struct ImpulseSet {
  std::array<Candidate, kMaxImpulses> impulses{};
  std::array<Eigen::Vector3d, kMaxImpulses> dv{};
  int count = 0;
};

core::Status validate_inputs(const astro::KeplerianElements& chief_mean_t0, const astro::RelativeOrbitalElements& roe0,
                                   const astro::RelativeOrbitalElements& roe_target, double tf,
                                   const ClosedFormSettings& settings, const core::EarthGravityConstants& gravity) {
  if (auto ok = validate_planner_chief(chief_mean_t0, "chief_mean_t0", gravity); !ok) return ok;
  if (auto ok = validate_roe(roe0, "roe0"); !ok) return ok;
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok;
  if (!std::isfinite(tf)) return core::Status{core::Problem::kNotFinite, "tf", "must be finite"};
  if (!std::isfinite(settings.earliest_burn_s) || settings.earliest_burn_s < 0.0) {
    return core::Status{core::Problem::kOutOfRange, "settings.earliest_burn_s", "must be finite and >= 0"};
  }
  if (!std::isfinite(settings.end_margin_s) || settings.end_margin_s < 0.0) {
    return core::Status{core::Problem::kOutOfRange, "settings.end_margin_s", "must be finite and >= 0"};
  }
  if (!std::isfinite(settings.min_window_orbits) || settings.min_window_orbits < 1.5) {
    return core::Status{core::Problem::kOutOfRange, "settings.min_window_orbits", "must be >= 1.5 (three-burn solution)"};
  }
  if (settings.normal_burns != 1 && settings.normal_burns != 2) {
    return core::Status{core::Problem::kOutOfRange, "settings.normal_burns", "must be 1 or 2"};
  }
  if (!std::isfinite(settings.terminal_tolerance_m) || settings.terminal_tolerance_m <= 0.0) {
    return core::Status{core::Problem::kOutOfRange, "settings.terminal_tolerance_m", "must be finite and positive"};
  }
  return {};
}

// Step 0: secular rates, the burn window (at least min_window_orbits long) and the pseudostate.
core::Outcome<ClosedFormProblem> set_up(const astro::KeplerianElements& chief_mean_t0, const astro::RelativeOrbitalElements& roe0,
                                       const astro::RelativeOrbitalElements& roe_target, double tf,
                                       const ClosedFormSettings& settings, const core::EarthGravityConstants& gravity) {
  ClosedFormProblem p;
  p.chief = &chief_mean_t0;
  p.gravity = &gravity;
  p.settings = &settings;
  p.rates = astro::j2_secular_rates(chief_mean_t0, gravity);
  p.u_dot = latitude_rate(p.rates);
  p.orbit = core::kTwoPi / p.u_dot;
  p.tf = tf;
  p.ts = settings.earliest_burn_s;
  p.te = tf - settings.end_margin_s;
  if (!(p.te - p.ts >= settings.min_window_orbits * p.orbit)) {
    return core::Status{core::Problem::kOutOfRange, "tf",
                        "horizon too short: the burn window must span settings.min_window_orbits orbits"};
  }
  p.a = chief_mean_t0.a;
  p.n = p.rates.n;
  p.u0 = chief_mean_t0.argp + chief_mean_t0.M;  // mean argument of latitude [rad]
  p.w = p.a * (roe_target - astro::j2_roe_stm(chief_mean_t0, tf, gravity) * roe0);
  return p;
}

// The time in the window at which a normal burn changes di along w_i: the pre-image direction
// at a trial time (docs/algorithms/control.md#out-of-plane-bound-with-j2), the first time whose
// mean argument of latitude is congruent to it modulo pi (either sign of dv_N works), then
// refined on the exact input matrix (the di effect b(t) of a unit normal burn parallel to w_i:
// g(t) = b(t) x w_i = 0 by the secant method, b rotating at ~u_dot).
double normal_burn_time(const ClosedFormProblem& p, const Eigen::Vector2d& wi) {
  using namespace astro::roe;
  const astro::KeplerianElements& chief = *p.chief;
  const auto pre_image_angle = [&](double t) {
    const double k = 2.0 * p.rates.kappa * std::sin(chief.i) * std::sin(chief.i) * (p.tf - t);
    return std::atan2(wi.y() - k * wi.x(), wi.x());
  };
  double tn = p.ts;
  for (int it = 0; it < 3; ++it) tn = next_phase_time(p.u0, p.u_dot, pre_image_angle(tn), core::kPi, p.ts);
  const auto cross = [&](double t) {
    const Matrix63 bt = p.b_at(t);
    return (bt(kDix, 2) * wi.y() - bt(kDiy, 2) * wi.x()) / wi.norm();
  };
  double t_prev = tn + 10.0;
  double g_prev = cross(t_prev);
  double g_cur = cross(tn);
  for (int it = 0; it < 8 && g_cur != 0.0 && g_cur != g_prev; ++it) {
    const double t_next = tn - g_cur * (tn - t_prev) / (g_cur - g_prev);
    t_prev = tn;
    g_prev = g_cur;
    tn = t_next;
    g_cur = cross(tn);
    if (std::abs(tn - t_prev) < 1e-6) break;
  }
  return std::clamp(tn, p.ts, p.te);
}

// Step 2: the normal burn(s) that remove the di part of w (two one orbit apart split it, so the
// buffer can spread each half); w_residual loses their effect.
core::Status add_normal_burns(const ClosedFormProblem& p, ImpulseSet& set, Vector6d& w_residual) {
  using namespace astro::roe;
  const Eigen::Vector2d wi(p.w[kDix], p.w[kDiy]);
  if (!(wi.norm() > 1e-12 * p.w.norm())) return {};
  const int burns = p.settings->normal_burns;
  const double tn = normal_burn_time(p, wi);
  std::array<double, 2> times{tn, tn + p.orbit};
  if (times[1] > p.te) times[1] = tn - p.orbit;
  if (burns == 2 && (times[1] < p.ts || times[1] > p.te)) {
    return core::Status{core::Problem::kOutOfRange, "settings.normal_burns", "the window has no room for two normal burns one orbit apart"};
  }
  Eigen::Vector2d sum_b = Eigen::Vector2d::Zero();
  for (int j = 0; j < burns; ++j) {
    const auto idx = static_cast<std::size_t>(set.count + j);
    set.impulses[idx] = Candidate{times[static_cast<std::size_t>(j)], p.b_at(times[static_cast<std::size_t>(j)])};
    const Matrix63& bj = set.impulses[idx].b;
    sum_b += Eigen::Vector2d(bj(kDix, 2), bj(kDiy, 2));
  }
  const double dv_n = sum_b.dot(wi) / sum_b.squaredNorm();
  for (int j = 0; j < burns; ++j) {
    const auto idx = static_cast<std::size_t>(set.count + j);
    set.dv[idx] = Eigen::Vector3d(0.0, 0.0, dv_n);
    w_residual -= set.impulses[idx].b * set.dv[idx];
  }
  set.count += burns;
  return {};
}

struct TangentialCandidates {
  std::array<Candidate, kMaxCandidates> at{};
  int count = 0;

  // Adds a candidate at t (clamped to the window) unless one lies within 1 s.
  void add(const ClosedFormProblem& p, double t) {
    t = std::clamp(t, p.ts, p.te);
    for (int k = 0; k < count; ++k) {
      if (std::abs(at[static_cast<std::size_t>(k)].t - t) < 1.0) return;
    }
    if (count < kMaxCandidates) at[static_cast<std::size_t>(count++)] = Candidate{t, p.b_at(t)};
  }
  // The tangential column of a B(t_k), rows da, dlambda, dex, dey.
  [[nodiscard]] Vector4d column(int k) const { return at[static_cast<std::size_t>(k)].b.col(1).head<4>(); }
};

// Candidate times of the tangential burns: the delta-e phased times u0 + u_dot t + argp_dot (tf
// - t) = phi_e + k pi (docs/algorithms/control.md#closed-form-planner), the first and last three
// of them; the window ends (the dlambda lever) and points a quarter and half orbit inside them.
TangentialCandidates tangential_candidates(const ClosedFormProblem& p, const Vector4d& r4) {
  TangentialCandidates cand;
  const double phi_e = std::atan2(r4[3], r4[2]);
  const double rate = p.u_dot - p.rates.argp_dot;
  const double phase0 = p.u0 + p.rates.argp_dot * p.tf;
  const double first = next_phase_time(phase0, rate, phi_e, core::kPi, p.ts);
  const double half = core::kPi / rate;
  const int phased = static_cast<int>(std::floor((p.te - first) / half)) + 1;
  for (int k = 0; k < std::min(phased, 3); ++k) cand.add(p, first + k * half);
  for (int k = std::max(3, phased - 3); k < phased; ++k) cand.add(p, first + k * half);
  for (double t : {p.ts, p.te, p.ts + 0.25 * p.orbit, p.te - 0.25 * p.orbit, p.ts + 0.5 * p.orbit, p.te - 0.5 * p.orbit}) {
    cand.add(p, t);
  }
  return cand;
}

// Scores one basis (3 columns in least squares, or 4 exactly) into `best` if it is better.
void consider_basis(const TangentialCandidates& cand, const Vector4d& r4, double n, const std::array<int, 4>& idx,
                    int size, Basis& best) {
  Vector4d x = Vector4d::Zero();
  Vector4d residual;
  if (size == 4) {
    Eigen::Matrix4d m;
    for (int j = 0; j < 4; ++j) m.col(j) = cand.column(idx[static_cast<std::size_t>(j)]);
    const Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
    if (lu.rank() < 4) return;
    x = lu.solve(r4);
    residual = r4 - m * x;
  } else {
    Eigen::Matrix<double, 4, 3> m;
    for (int j = 0; j < 3; ++j) m.col(j) = cand.column(idx[static_cast<std::size_t>(j)]);
    const Eigen::Matrix3d normal = m.transpose() * m;
    const Eigen::FullPivLU<Eigen::Matrix3d> lu(normal);
    if (lu.rank() < 3) return;
    const Eigen::Vector3d x3 = lu.solve(m.transpose() * r4);
    x.head<3>() = x3;
    residual = r4 - m * x3;
  }
  if (!x.allFinite()) return;
  const double score = x.cwiseAbs().sum() + n * residual.norm();
  if (score < best.score * (1.0 - 1e-12)) {
    best.index = idx;
    best.size = size;
    best.x = x;
    best.score = score;
  }
}

// Enumerates the bases of the l1 problem min sum|x| s.t. sum x_k c_k = r4. 3-subsets are solved
// in least squares (the phased burns leave only the small perpendicular delta-e residual of the
// first-order phasing); each basis is scored by its l1 cost plus n ||residual|| (the order of the
// cost of removing the residual in step 4).
Basis best_tangential_basis(const TangentialCandidates& cand, const Vector4d& r4, double n) {
  Basis best;
  best.score = std::numeric_limits<double>::infinity();
  const int nc = cand.count;
  for (int i = 0; i < nc; ++i)
    for (int j = i + 1; j < nc; ++j)
      for (int k = j + 1; k < nc; ++k) consider_basis(cand, r4, n, {i, j, k, 0}, 3, best);
  for (int i = 0; i < nc; ++i)
    for (int j = i + 1; j < nc; ++j)
      for (int k = j + 1; k < nc; ++k)
        for (int l = k + 1; l < nc; ++l) consider_basis(cand, r4, n, {i, j, k, l}, 4, best);
  return best;
}

// Step 3: tangential burns for the in-plane residual (da, dlambda, de), merged with a normal
// burn at the same time (one impulse serves both planes).
core::Status add_tangential_burns(const ClosedFormProblem& p, const Vector6d& w_residual, ImpulseSet& set) {
  const Vector4d r4 = in_plane(w_residual);
  if (!(r4.norm() > 1e-12 * p.w.norm())) return {};
  const TangentialCandidates cand = tangential_candidates(p, r4);
  const Basis best = best_tangential_basis(cand, r4, p.n);
  if (best.size == 0) return core::Status{core::Problem::kSingular, "roe_target", "singular geometry: no tangential burn basis"};
  const double x_scale = best.x.cwiseAbs().maxCoeff();
  for (int j = 0; j < best.size; ++j) {
    const double xj = best.x[j];
    if (std::abs(xj) <= 1e-12 * x_scale) continue;
    const Candidate& c = cand.at[static_cast<std::size_t>(best.index[static_cast<std::size_t>(j)])];
    int target = -1;
    for (int m = 0; m < set.count; ++m) {
      if (std::abs(set.impulses[static_cast<std::size_t>(m)].t - c.t) < 1e-6) target = m;
    }
    if (target < 0) {
      target = set.count++;
      set.impulses[static_cast<std::size_t>(target)] = c;
      set.dv[static_cast<std::size_t>(target)].setZero();
    }
    set.dv[static_cast<std::size_t>(target)].y() += xj;
  }
  return {};
}

// Step 4: minimum-norm correction of all impulse vectors, v += M' (M M')^-1 (w - M v), twice;
// the plan must then reach w within settings.terminal_tolerance_m.
core::Status correct_min_norm(const ClosedFormProblem& p, ImpulseSet& set) {
  const int count = set.count;
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 3 * kMaxImpulses> m(6, 3 * count);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * kMaxImpulses, 1> v(3 * count);
  for (int k = 0; k < count; ++k) {
    m.middleCols<3>(3 * k) = set.impulses[static_cast<std::size_t>(k)].b;
    v.segment<3>(3 * k) = set.dv[static_cast<std::size_t>(k)];
  }
  Vector6d residual = p.w - m * v;
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Matrix<double, 6, 6> mmt = m * m.transpose();
    // A relative 1e-14 ridge keeps the factorisation defined when the impulses do not span all
    // six directions; the residual test below then reports the geometry as singular.
    mmt.diagonal().array() += 1e-14 * mmt.trace();
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(mmt);
    const Vector6d y = ldlt.solve(residual);
    if (!y.allFinite()) break;
    v += m.transpose() * y;
    residual = p.w - m * v;
  }
  if (!(residual.norm() <= p.settings->terminal_tolerance_m)) {
    return core::Status{core::Problem::kSingular, "roe_target", "singular geometry: the impulses cannot reach the target"};
  }
  for (int k = 0; k < count; ++k) set.dv[static_cast<std::size_t>(k)] = v.segment<3>(3 * k);
  return {};
}

}  // namespace

core::Result<ManeuverPlan> plan_closed_form(const astro::KeplerianElements& chief_mean_t0,
                                            const astro::RelativeOrbitalElements& roe0,
                                            const astro::RelativeOrbitalElements& roe_target, double tf,
                                            const ClosedFormSettings& settings,
                                            const core::EarthGravityConstants& gravity) {
  ManeuverPlan plan;
  plan.impulses.reserve(kMaxClosedFormImpulses);
  if (auto ok = plan_closed_form_into(plan, chief_mean_t0, roe0, roe_target, tf, settings, gravity); !ok) return ok.error();
  return plan;
}

core::Status plan_closed_form_into(ManeuverPlan& plan, const astro::KeplerianElements& chief_mean_t0,
                                         const astro::RelativeOrbitalElements& roe0,
                                         const astro::RelativeOrbitalElements& roe_target, double tf,
                                         const ClosedFormSettings& settings, const core::EarthGravityConstants& gravity) {
  plan.impulses.clear();
  plan.dv_total_mps = 0.0;
  plan.dv_lower_bound_mps = 0.0;
  if (auto ok = validate_inputs(chief_mean_t0, roe0, roe_target, tf, settings, gravity); !ok) return ok;
  const auto problem = set_up(chief_mean_t0, roe0, roe_target, tf, settings, gravity);
  if (!problem.ok()) return problem.status();
  const ClosedFormProblem& p = *problem;
  // 1. The pseudostate and its delta-v lower bound.
  auto bound = delta_v_lower_bound(chief_mean_t0, p.w / p.a, tf - p.ts, gravity);
  if (!bound.ok()) return bound.status();
  if (p.w.norm() == 0.0) {  // already on target: no impulse
    plan.roe_final_predicted = roe_target;
    return {};
  }
  // 2-4. Normal burns, tangential burns, minimum-norm correction.
  ImpulseSet set;
  Vector6d w_residual = p.w;
  if (auto ok = add_normal_burns(p, set, w_residual); !ok) return ok;
  if (auto ok = add_tangential_burns(p, w_residual, set); !ok) return ok;
  if (auto ok = correct_min_norm(p, set); !ok) return ok;
  for (int k = 0; k < set.count; ++k) {
    plan.impulses.push_back(Impulse{set.impulses[static_cast<std::size_t>(k)].t, set.dv[static_cast<std::size_t>(k)]});
  }
  std::sort(plan.impulses.begin(), plan.impulses.end(), [](const Impulse& x, const Impulse& y) { return x.t < y.t; });
  plan.dv_total_mps = total_delta_v(plan.impulses);
  plan.dv_lower_bound_mps = bound.value().total;
  plan.roe_final_predicted = predict_roe(chief_mean_t0, roe0, plan.impulses, tf, gravity);
  return {};
}

}  // namespace visors::control
