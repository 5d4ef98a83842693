// An outside program with the installed package: the closed-form planner (visors::control) and the
// integer least-squares search (visors::ambiguity), each checked against a published value.
// Exit 0 when both agree, 1 otherwise.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <utility>

#include <Eigen/Core>

#include <visors/control/closed_form_planner.hpp>
#include <visors/core/version.hpp>
#include <visors/nav/integer_least_squares.hpp>

namespace {

// Standby -> science of the mission (a*dROE [m]: standby (0, 0, 0, 200, 0, 200), science
// (-2.62, 45.21, -34.51, 4.78, -18.72, 2.72)) in 1.5 orbits of a circular Keplerian chief. The
// minimum delta-v of a relative-eccentricity change is n a |d(delta e)| / 2 and of a relative-
// inclination change n a |d(delta i)| (Gaias & D'Amico, JGCD 38(6), 2015, Table 1); the planner's
// in-plane and normal burns together reach their sum.
bool plan_reaches_the_bound() {
  const double mu = 3.986004418e14;  // [m^3/s^2]
  const double a = 6378136.3 + 500e3;  // [m]
  const double deg = std::numbers::pi / 180.0;
  const visors::astro::KeplerianElements chief{a, 0.0, 97.8 * deg, 157.5 * deg, 0.0, 0.0};
  visors::astro::RelativeOrbitalElements standby, science;
  standby << 0, 0, 0, 200, 0, 200;
  science << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;
  standby /= a;
  science /= a;
  const double n = std::sqrt(mu / (a * a * a));  // [rad/s]
  const visors::core::EarthGravityConstants kepler{mu, 6378136.3, 0.0};
  const auto plan = visors::control::plan_closed_form(chief, standby, science, 3.0 * std::numbers::pi / n, {}, kepler);
  if (!plan) {
    std::fprintf(stderr, "plan_closed_form: %s\n", plan.error().describe().c_str());
    return false;
  }
  const double de_m = std::hypot(-34.51, 4.78 - 200.0), di_m = std::hypot(-18.72, 2.72 - 200.0);
  const double bound = n * de_m / 2.0 + n * di_m;  // [m/s]
  const double miss_m = a * (plan->roe_final_predicted - science).norm();
  std::printf("closed-form plan: %.5f m/s against the bound %.5f m/s, %zu burns, terminal miss %.1e m\n",
              plan->dv_total_mps, bound, plan->impulses.size(), miss_m);
  return std::abs(plan->dv_total_mps - bound) < 1e-5 && miss_m < 1e-6;
}

// Float ambiguities 0.2 and 0.1 cycles from (1, -1) with uncorrelated 0.1-cycle sigmas: the
// integer least-squares solution of a diagonal covariance is the componentwise rounding
// (Teunissen, J. Geodesy 70, 1995), runner-up (2, -1): ratio (0.64 + 0.01) / (0.04 + 0.01) = 13.
bool ils_finds_the_rounding() {
  auto created = visors::nav::IntegerLeastSquares::create();
  if (!created) return false;
  visors::nav::IntegerLeastSquares ils = std::move(created).value();
  if (ils.resolve(Eigen::Vector2d(1.2, -0.9), 0.01 * Eigen::Matrix2d::Identity()) != visors::nav::IlsStatus::kOk) {
    return false;
  }
  const auto& s = ils.solution();
  std::printf("integer least squares: (%g, %g), ratio %.1f\n", s.a(0, 0), s.a(1, 0), s.ratio);
  return s.found >= 1 && s.a(0, 0) == 1.0 && s.a(1, 0) == -1.0 && std::abs(s.ratio - 13.0) < 1e-9;
}

}  // namespace

int main() {
  std::printf("visors %.*s, installed package\n", static_cast<int>(visors::core::kVersion.size()),
              visors::core::kVersion.data());
  const bool plan_ok = plan_reaches_the_bound();
  const bool ils_ok = ils_finds_the_rounding();
  return plan_ok && ils_ok ? 0 : 1;
}
