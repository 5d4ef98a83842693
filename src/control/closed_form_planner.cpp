#include "control/closed_form_planner.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "astro/j2_secular.hpp"
#include "astro/roe_stm.hpp"
#include "control/delta_v_lower_bound.hpp"
#include "control/impulse_effect.hpp"

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

core::Result<bool> plan_closed_form_into(ManeuverPlan& plan, const astro::KeplerianElements& chief_mean_t0,
                                         const astro::RelativeOrbitalElements& roe0,
                                         const astro::RelativeOrbitalElements& roe_target, double tf,
                                         const ClosedFormSettings& settings, const core::EarthGravityConstants& gravity) {
  using namespace astro::roe;
  plan.impulses.clear();
  plan.dv_total = 0.0;
  plan.dv_lower_bound = 0.0;
  // ---- validation --------------------------------------------------------------------------
  if (auto ok = validate_planner_chief(chief_mean_t0, "chief_mean_t0", gravity); !ok) return ok.error();
  if (auto ok = validate_roe(roe0, "roe0"); !ok) return ok.error();
  if (auto ok = validate_roe(roe_target, "roe_target"); !ok) return ok.error();
  if (!std::isfinite(tf)) return core::Error{"tf", "must be finite"};
  if (!std::isfinite(settings.earliest_burn) || settings.earliest_burn < 0.0) {
    return core::Error{"settings.earliest_burn", "must be finite and >= 0"};
  }
  if (!std::isfinite(settings.end_margin) || settings.end_margin < 0.0) {
    return core::Error{"settings.end_margin", "must be finite and >= 0"};
  }
  if (!std::isfinite(settings.min_window_orbits) || settings.min_window_orbits < 1.5) {
    return core::Error{"settings.min_window_orbits", "must be >= 1.5 (three-burn solution)"};
  }
  if (settings.normal_burns != 1 && settings.normal_burns != 2) {
    return core::Error{"settings.normal_burns", "must be 1 or 2"};
  }
  if (!std::isfinite(settings.terminal_tolerance) || settings.terminal_tolerance <= 0.0) {
    return core::Error{"settings.terminal_tolerance", "must be finite and positive"};
  }

  const astro::J2SecularRates rates = astro::j2_secular_rates(chief_mean_t0, gravity);
  const double u_dot = latitude_rate(rates);
  const double orbit = core::kTwoPi / u_dot;  // [s]
  const double ts = settings.earliest_burn;
  const double te = tf - settings.end_margin;
  if (!(te - ts >= settings.min_window_orbits * orbit)) {
    return core::Error{"tf", "horizon too short: the burn window must span at least " +
                                 std::to_string(settings.min_window_orbits) + " orbits (" +
                                 std::to_string(settings.min_window_orbits * orbit) + " s)"};
  }
  const double a = chief_mean_t0.a;
  const double n = rates.n;
  const double u0 = chief_mean_t0.argp + chief_mean_t0.M;  // mean argument of latitude [rad]

  // ---- 1. pseudostate, in metres -------------------------------------------------------------
  const Vector6d w = a * (roe_target - astro::j2_roe_stm(chief_mean_t0, tf, gravity) * roe0);
  auto bound = delta_v_lower_bound(chief_mean_t0, w / a, tf - ts, gravity);
  if (!bound.ok()) return bound.error();

  auto b_at = [&](double t) -> Matrix63 { return a * impulse_effect(chief_mean_t0, t, tf, gravity); };

  std::array<Candidate, kMaxImpulses> impulses{};
  std::array<Eigen::Vector3d, kMaxImpulses> dv{};
  int count = 0;
  const double w_scale = w.norm();
  if (w_scale == 0.0) {  // already on target: no impulse
    plan.roe_final_predicted = roe_target;
    return true;
  }

  // ---- 2. normal burn(s) ---------------------------------------------------------------------
  Vector6d w_in_residual = w;
  const Eigen::Vector2d wi(w[kDix], w[kDiy]);
  if (wi.norm() > 1e-12 * w_scale) {
    // Pre-image direction at a trial time (digest 4.6), then the first time in the window whose
    // mean argument of latitude is congruent to it modulo pi (either sign of dv_N works).
    auto pre_image_angle = [&](double t) {
      const double k = 2.0 * rates.kappa * std::sin(chief_mean_t0.i) * std::sin(chief_mean_t0.i) * (tf - t);
      return std::atan2(wi.y() - k * wi.x(), wi.x());
    };
    double tn = ts;
    for (int it = 0; it < 3; ++it) tn = next_phase_time(u0, u_dot, pre_image_angle(tn), core::kPi, ts);
    // Refine on the exact input matrix: the di effect b(t) of a unit normal burn must be parallel
    // to w_i; g(t) = b(t) x w_i = 0 by the secant method (b rotates at ~u_dot).
    auto cross = [&](double t) {
      const Matrix63 bt = b_at(t);
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
    tn = std::clamp(tn, ts, te);
    std::array<double, 2> times{tn, tn + orbit};
    if (times[1] > te) times[1] = tn - orbit;
    if (settings.normal_burns == 2 && (times[1] < ts || times[1] > te)) {
      return core::Error{"settings.normal_burns", "the window has no room for two normal burns one orbit apart"};
    }
    Eigen::Vector2d sum_b = Eigen::Vector2d::Zero();
    for (int j = 0; j < settings.normal_burns; ++j) {
      impulses[static_cast<std::size_t>(count + j)] = Candidate{times[static_cast<std::size_t>(j)],
                                                                b_at(times[static_cast<std::size_t>(j)])};
      const Matrix63& bj = impulses[static_cast<std::size_t>(count + j)].b;
      sum_b += Eigen::Vector2d(bj(kDix, 2), bj(kDiy, 2));
    }
    const double dv_n = sum_b.dot(wi) / sum_b.squaredNorm();
    for (int j = 0; j < settings.normal_burns; ++j) {
      const auto idx = static_cast<std::size_t>(count + j);
      dv[idx] = Eigen::Vector3d(0.0, 0.0, dv_n);
      w_in_residual -= impulses[idx].b * dv[idx];
    }
    count += settings.normal_burns;
  }

  // ---- 3. tangential burns -------------------------------------------------------------------
  const Vector4d r4 = in_plane(w_in_residual);
  if (r4.norm() > 1e-12 * w_scale) {
    std::array<Candidate, kMaxCandidates> cand{};
    int nc = 0;
    auto add = [&](double t) {
      t = std::clamp(t, ts, te);
      for (int k = 0; k < nc; ++k) {
        if (std::abs(cand[static_cast<std::size_t>(k)].t - t) < 1.0) return;  // merge within 1 s
      }
      if (nc < kMaxCandidates) cand[static_cast<std::size_t>(nc++)] = Candidate{t, b_at(t)};
    };
    // delta-e phased times: u0 + u_dot t + argp_dot (tf - t) = phi_e + k pi (digest 4.6).
    const double phi_e = std::atan2(r4[3], r4[2]);
    const double rate = u_dot - rates.argp_dot;
    const double phase0 = u0 + rates.argp_dot * tf;
    const double first = next_phase_time(phase0, rate, phi_e, core::kPi, ts);
    const double half = core::kPi / rate;
    const int phased = static_cast<int>(std::floor((te - first) / half)) + 1;
    for (int k = 0; k < std::min(phased, 3); ++k) add(first + k * half);
    for (int k = std::max(3, phased - 3); k < phased; ++k) add(first + k * half);
    // Window ends (dlambda lever) and points a quarter / half orbit inside them.
    for (double t : {ts, te, ts + 0.25 * orbit, te - 0.25 * orbit, ts + 0.5 * orbit, te - 0.5 * orbit}) add(t);

    // Enumerate bases of the l1 problem min sum|x| s.t. sum x_k c_k = r4, c_k the tangential
    // column of a B(t_k) (rows da, dlambda, dex, dey). 3-subsets are solved in least squares (the
    // phased burns leave only the small perpendicular delta-e residual of the first-order
    // phasing); each basis is scored by its l1 cost plus n ||residual|| (the order of the cost
    // of removing the residual in step 4).
    Basis best;
    best.score = std::numeric_limits<double>::infinity();
    auto column = [&](int k) -> Vector4d { return cand[static_cast<std::size_t>(k)].b.col(1).head<4>(); };
    auto consider = [&](const std::array<int, 4>& idx, int size) {
      Vector4d x = Vector4d::Zero();
      Vector4d residual;
      if (size == 4) {
        Eigen::Matrix4d m;
        for (int j = 0; j < 4; ++j) m.col(j) = column(idx[static_cast<std::size_t>(j)]);
        const Eigen::FullPivLU<Eigen::Matrix4d> lu(m);
        if (lu.rank() < 4) return;
        x = lu.solve(r4);
        residual = r4 - m * x;
      } else {
        Eigen::Matrix<double, 4, 3> m;
        for (int j = 0; j < 3; ++j) m.col(j) = column(idx[static_cast<std::size_t>(j)]);
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
    };
    for (int i = 0; i < nc; ++i)
      for (int j = i + 1; j < nc; ++j)
        for (int k = j + 1; k < nc; ++k) consider({i, j, k, 0}, 3);
    for (int i = 0; i < nc; ++i)
      for (int j = i + 1; j < nc; ++j)
        for (int k = j + 1; k < nc; ++k)
          for (int l = k + 1; l < nc; ++l) consider({i, j, k, l}, 4);
    if (best.size == 0) return core::Error{"roe_target", "singular geometry: no tangential burn basis"};
    const double x_scale = best.x.cwiseAbs().maxCoeff();
    for (int j = 0; j < best.size; ++j) {
      const double xj = best.x[j];
      if (std::abs(xj) <= 1e-12 * x_scale) continue;
      const Candidate& c = cand[static_cast<std::size_t>(best.index[static_cast<std::size_t>(j)])];
      // Merge with a normal burn at the same time (one impulse serves both planes).
      int target = -1;
      for (int m = 0; m < count; ++m) {
        if (std::abs(impulses[static_cast<std::size_t>(m)].t - c.t) < 1e-6) target = m;
      }
      if (target < 0) {
        target = count++;
        impulses[static_cast<std::size_t>(target)] = c;
        dv[static_cast<std::size_t>(target)].setZero();
      }
      dv[static_cast<std::size_t>(target)].y() += xj;
    }
  }

  // ---- 4. minimum-norm correction of all impulse vectors ---------------------------------------
  Eigen::Matrix<double, 6, Eigen::Dynamic, 0, 6, 3 * kMaxImpulses> m(6, 3 * count);
  Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 3 * kMaxImpulses, 1> v(3 * count);
  for (int k = 0; k < count; ++k) {
    m.middleCols<3>(3 * k) = impulses[static_cast<std::size_t>(k)].b;
    v.segment<3>(3 * k) = dv[static_cast<std::size_t>(k)];
  }
  Vector6d residual = w - m * v;
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Matrix<double, 6, 6> mmt = m * m.transpose();
    // A relative 1e-14 ridge keeps the factorisation defined when the impulses do not span all
    // six directions; the residual test below then reports the geometry as singular.
    mmt.diagonal().array() += 1e-14 * mmt.trace();
    const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(mmt);
    const Vector6d y = ldlt.solve(residual);
    if (!y.allFinite()) break;
    v += m.transpose() * y;
    residual = w - m * v;
  }
  if (!(residual.norm() <= settings.terminal_tolerance)) {
    return core::Error{"roe_target", "singular geometry: the impulses cannot reach the target (residual " +
                                         std::to_string(residual.norm()) + " m)"};
  }

  for (int k = 0; k < count; ++k) {
    plan.impulses.push_back(Impulse{impulses[static_cast<std::size_t>(k)].t, v.segment<3>(3 * k)});
  }
  std::sort(plan.impulses.begin(), plan.impulses.end(),
            [](const Impulse& x, const Impulse& y) { return x.t < y.t; });
  plan.dv_total = total_delta_v(plan.impulses);
  plan.dv_lower_bound = bound.value().total;
  plan.roe_final_predicted = predict_roe(chief_mean_t0, roe0, plan.impulses, tf, gravity);
  return true;
}

}  // namespace visors::control
