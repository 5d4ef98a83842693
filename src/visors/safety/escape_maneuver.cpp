#include "visors/safety/escape_maneuver.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <Eigen/LU>

#include "visors/astro/control_input_matrix.hpp"
#include "visors/astro/j2_secular.hpp"
#include "visors/astro/roe_stm.hpp"

namespace visors::safety {
namespace {

using astro::RelativeOrbitalElements;
namespace idx = astro::roe;

constexpr int kMaxPsiSamples = 720;
constexpr int kMaxCandidates = kMaxPsiSamples + 2;
// A direction for which the 3x3 system is (near) singular yields an enormous dv; anything above
// this is discarded outright [m/s].
constexpr double kDvDiscard = 10.0;

struct Candidate {
  Eigen::Vector3d dv = Eigen::Vector3d::Zero();
  double norm = 0.0;
};

// 2-D cross product z-component.
double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

// Solves conditions (i)-(ii) of the header for the common direction psi. False if singular.
bool solve_for_direction(const astro::ControlInputMatrix& gamma, const RelativeOrbitalElements& roe_b,
                         double da_after, double psi, Candidate& out) {
  const double dx = std::cos(psi);
  const double dy = std::sin(psi);
  Eigen::Matrix3d m;
  Eigen::Vector3d rhs;
  m.row(0) = gamma.row(idx::kDa);
  rhs[0] = da_after - roe_b[idx::kDa];
  // cross(de_b + Gamma_e dv, d) = 0
  m.row(1) = dy * gamma.row(idx::kDex) - dx * gamma.row(idx::kDey);
  rhs[1] = -cross(roe_b[idx::kDex], roe_b[idx::kDey], dx, dy);
  m.row(2) = dy * gamma.row(idx::kDix) - dx * gamma.row(idx::kDiy);
  rhs[2] = -cross(roe_b[idx::kDix], roe_b[idx::kDiy], dx, dy);
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(m);
  if (!lu.isInvertible()) return false;
  out.dv = lu.solve(rhs);
  out.norm = out.dv.norm();
  return std::isfinite(out.norm) && out.norm < kDvDiscard;
}

}  // namespace

core::Status validate(const EscapeSettings& s) {
  if (!(s.epsilon_m >= 0.0) || !std::isfinite(s.epsilon_m)) return core::Status{core::Problem::kOutOfRange, "epsilon_m", "must be a finite number >= 0 m"};
  if (!(s.da_target_m > 0.0) || !std::isfinite(s.da_target_m)) return core::Status{core::Problem::kOutOfRange, "da_target_m", "must be a finite number > 0 m"};
  if (!(s.q_sigma >= 0.0) || s.q_sigma > 10.0) return core::Status{core::Problem::kOutOfRange, "q_sigma", "must be in [0, 10]"};
  if (!(s.horizon_orbits > 0.0) || s.horizon_orbits > 100.0) return core::Status{core::Problem::kOutOfRange, "horizon_orbits", "must be in (0, 100] orbits"};
  if (s.samples_per_orbit < 8 || s.samples_per_orbit > 100000) return core::Status{core::Problem::kOutOfRange, "samples_per_orbit", "must be in [8, 100000]"};
  if (s.psi_samples < 4 || s.psi_samples > kMaxPsiSamples) return core::Status{core::Problem::kOutOfRange, "psi_samples", "must be in [4, 720]"};
  if (!(s.time_step_s >= 0.1) || !std::isfinite(s.time_step_s)) return core::Status{core::Problem::kOutOfRange, "time_step_s", "must be a finite number >= 0.1 s"};
  if (!(s.search_window_orbits >= 0.0) || s.search_window_orbits > 10.0) {
    return core::Status{core::Problem::kOutOfRange, "search_window_orbits", "must be in [0, 10] orbits"};
  }
  if (!(s.dv_sigma_mps >= 0.0) || !std::isfinite(s.dv_sigma_mps)) return core::Status{core::Problem::kOutOfRange, "dv_sigma_mps", "must be a finite number >= 0 m/s"};
  return {};
}

namespace {

core::Status check_escape_inputs(const astro::KeplerianElements& chief_mean_t0, const RelativeOrbitalElements& roe,
                                       const RoeCovariance& covariance, double t_earliest,
                                       const EscapeSettings& settings, const core::EarthGravityConstants& gravity) {
  if (const core::Status checked = validate(settings); !checked) return checked;
  if (const core::Status inputs = validate_safety_inputs(chief_mean_t0, roe, covariance, gravity); !inputs) return inputs;
  if (!(t_earliest >= 0.0) || !std::isfinite(t_earliest)) return core::Status{core::Problem::kOutOfRange, "t_earliest", "must be a finite number >= 0 s"};
  return {};
}

// Condition (iii) is judged with the escape's margin, plane, horizon and sampling.
PassiveSafetySettings safety_after_escape(const EscapeSettings& settings) {
  PassiveSafetySettings safety;
  safety.epsilon_m = settings.epsilon_m;
  safety.horizon_orbits = settings.horizon_orbits;
  safety.q_sigma = settings.q_sigma;
  safety.plane = settings.plane;
  safety.samples_per_orbit = settings.samples_per_orbit;
  return safety;
}

// The linear model at a trial burn time t: chief, ROE and covariance carried from t0 by the J2
// STM, the control input matrix, and the covariance just after the burn (execution error added).
struct BurnPoint {
  double t;
  astro::KeplerianElements chief_b;
  RelativeOrbitalElements roe_b;
  astro::ControlInputMatrix gamma;
  RoeCovariance p_after;
};

BurnPoint burn_point(const astro::KeplerianElements& chief_mean_t0, const RelativeOrbitalElements& roe,
                     const RoeCovariance& covariance, double t, const Eigen::Matrix3d& q_dv,
                     const core::EarthGravityConstants& gravity) {
  const astro::KeplerianElements chief_b = astro::propagate_mean_j2(chief_mean_t0, t, gravity);
  const astro::RoeStm phi = astro::j2_roe_stm(chief_mean_t0, t, gravity);
  const RelativeOrbitalElements roe_b = phi * roe;
  const astro::ControlInputMatrix gamma = astro::control_input_matrix(chief_b, gravity.mu);
  RoeCovariance p_after = phi * covariance * phi.transpose() + gamma * q_dv * gamma.transpose();
  p_after = 0.5 * (p_after + p_after.transpose()).eval();
  return BurnPoint{t, chief_b, roe_b, gamma, p_after};
}

// (i): drift away from the chief, |a da| = da_target + q sigma(a da); returns da after the burn.
double da_after_burn(const BurnPoint& b, double a, const EscapeSettings& settings) {
  const double sign = b.roe_b[idx::kDlambda] > 0.0 ? -1.0 : 1.0;
  const double sigma_ada = a * std::sqrt(std::max(0.0, b.p_after(idx::kDa, idx::kDa)));
  return sign * (settings.da_target_m + settings.q_sigma * sigma_ada) / a;
}

// The impulses meeting (i)-(ii), ranked by |dv| (fixed capacity: no allocation).
struct CandidateSet {
  std::array<Candidate, kMaxCandidates> candidates;
  std::array<int, kMaxCandidates> order{};
  int count = 0;

  [[nodiscard]] const Candidate& ranked(int j) const {
    return candidates[static_cast<std::size_t>(order[static_cast<std::size_t>(j)])];
  }
};

// (ii): candidate directions, the grid plus the current phases of de and di (whose solution
// needs no rotation of that vector).
void solve_candidates(const BurnPoint& b, double da_after, int psi_samples, CandidateSet& set) {
  int count = 0;
  const auto add = [&](double psi) {
    if (solve_for_direction(b.gamma, b.roe_b, da_after, psi, set.candidates[static_cast<std::size_t>(count)])) ++count;
  };
  for (int j = 0; j < psi_samples; ++j) add(core::kPi * j / psi_samples);
  add(std::atan2(b.roe_b[idx::kDey], b.roe_b[idx::kDex]));
  add(std::atan2(b.roe_b[idx::kDiy], b.roe_b[idx::kDix]));
  for (int j = 0; j < count; ++j) set.order[static_cast<std::size_t>(j)] = j;
  std::sort(set.order.begin(), set.order.begin() + count, [&](int x, int y) {
    return set.candidates[static_cast<std::size_t>(x)].norm < set.candidates[static_cast<std::size_t>(y)].norm;
  });
  set.count = count;
}

// Quick rejection: with parallel vectors the RN separation cannot exceed
// a min(|de|, |di|) + |a da| (+ O(e) map terms, 1 m allowance).
bool cannot_be_safe(const RelativeOrbitalElements& roe_after, double a, const PassiveSafetySettings& safety) {
  const double de = std::hypot(roe_after[idx::kDex], roe_after[idx::kDey]);
  const double di = std::hypot(roe_after[idx::kDix], roe_after[idx::kDiy]);
  return safety.plane == SafetyPlane::kRadialNormal &&
         a * (std::min(de, di) + std::abs(roe_after[idx::kDa])) + 1.0 < safety.epsilon_m;
}

// (iii): the cheapest candidate that is passively safe at q sigma, written to `out` (true), or
// none at this burn time (false).
core::Outcome<bool> first_safe_candidate(const BurnPoint& b, const CandidateSet& set, double a, double period,
                                        const PassiveSafetySettings& safety,
                                        const core::EarthGravityConstants& gravity, EscapeManeuver& out) {
  for (int j = 0; j < set.count; ++j) {
    const Candidate& c = set.ranked(j);
    const RelativeOrbitalElements roe_after = b.roe_b + b.gamma * c.dv;
    if (cannot_be_safe(roe_after, a, safety)) continue;
    const auto assessment = evaluate_passive_safety(b.chief_b, roe_after, b.p_after, safety, gravity);
    if (!assessment) return assessment.status();
    if (!assessment->safe) continue;
    out.impulse = control::Impulse{b.t, c.dv};
    out.roe_before = b.roe_b;
    out.roe_after = roe_after;
    out.covariance_after = b.p_after;
    out.safety_after = assessment.value();
    const RelativeOrbitalElements one_orbit = astro::j2_roe_stm(b.chief_b, period, gravity) * roe_after;
    out.drift_per_orbit_m = a * (one_orbit[idx::kDlambda] - roe_after[idx::kDlambda]);
    return true;
  }
  return false;
}

}  // namespace

core::Outcome<EscapeManeuver> plan_escape(const astro::KeplerianElements& chief_mean_t0,
                                         const RelativeOrbitalElements& roe, const RoeCovariance& covariance,
                                         double t_earliest, const EscapeSettings& settings,
                                         const core::EarthGravityConstants& gravity) {
  if (auto ok = check_escape_inputs(chief_mean_t0, roe, covariance, t_earliest, settings, gravity); !ok) return ok;
  const PassiveSafetySettings safety = safety_after_escape(settings);
  const double a = chief_mean_t0.a;
  const double period = orbital_period(chief_mean_t0, gravity.mu);
  const double t_last = t_earliest + settings.search_window_orbits * period;
  const Eigen::Matrix3d q_dv = Eigen::Matrix3d::Identity() * (settings.dv_sigma_mps * settings.dv_sigma_mps);

  // The first burn time t_earliest + k time_step with a safe candidate: "as soon as allowed".
  CandidateSet set;
  EscapeManeuver out;
  for (long k = 0;; ++k) {
    const double t = t_earliest + settings.time_step_s * static_cast<double>(k);
    if (t > t_last + 1e-9) break;
    const BurnPoint b = burn_point(chief_mean_t0, roe, covariance, t, q_dv, gravity);
    solve_candidates(b, da_after_burn(b, a, settings), settings.psi_samples, set);
    const auto found = first_safe_candidate(b, set, a, period, safety, gravity, out);
    if (!found) return found.status();
    if (*found) return out;
  }
  return core::Status{core::Problem::kInfeasible, "escape", "no single impulse in the search window meets the safety margin"};
}

}  // namespace visors::safety
