#include "visors/dynamics/dormand_prince87.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace visors::dynamics {
namespace {

constexpr int kStages = DormandPrince87Tableau::kStages;

// RK8(7)13M, Prince & Dormand (1981). The coefficients are the published rationals, written as
// quotients so that they can be compared with the paper term by term; their double values satisfy
// all 200 order conditions up to order 8 (b8) and the 85 up to order 7 (b7) to round-off
// (tests/dynamics/test_dormand_prince87.cpp). a[i][j] = 0 for j >= i (explicit method); the zero
// columns 2 and 3 of the later rows are part of the construction (simplifying assumptions).
constexpr DormandPrince87Tableau kTableau{
    // c
    {0.0, 1.0 / 18.0, 1.0 / 12.0, 1.0 / 8.0, 5.0 / 16.0, 3.0 / 8.0, 59.0 / 400.0, 93.0 / 200.0,
     5490023248.0 / 9719169821.0, 13.0 / 20.0, 1201146811.0 / 1299019798.0, 1.0, 1.0},
    // a
    {{
        {},
        {1.0 / 18.0},
        {1.0 / 48.0, 1.0 / 16.0},
        {1.0 / 32.0, 0.0, 3.0 / 32.0},
        {5.0 / 16.0, 0.0, -75.0 / 64.0, 75.0 / 64.0},
        {3.0 / 80.0, 0.0, 0.0, 3.0 / 16.0, 3.0 / 20.0},
        {29443841.0 / 614563906.0, 0.0, 0.0, 77736538.0 / 692538347.0,
         -28693883.0 / 1125000000.0, 23124283.0 / 1800000000.0},
        {16016141.0 / 946692911.0, 0.0, 0.0, 61564180.0 / 158732637.0, 22789713.0 / 633445777.0,
         545815736.0 / 2771057229.0, -180193667.0 / 1043307555.0},
        {39632708.0 / 573591083.0, 0.0, 0.0, -433636366.0 / 683701615.0,
         -421739975.0 / 2616292301.0, 100302831.0 / 723423059.0, 790204164.0 / 839813087.0,
         800635310.0 / 3783071287.0},
        {246121993.0 / 1340847787.0, 0.0, 0.0, -37695042795.0 / 15268766246.0,
         -309121744.0 / 1061227803.0, -12992083.0 / 490766935.0, 6005943493.0 / 2108947869.0,
         393006217.0 / 1396673457.0, 123872331.0 / 1001029789.0},
        {-1028468189.0 / 846180014.0, 0.0, 0.0, 8478235783.0 / 508512852.0,
         1311729495.0 / 1432422823.0, -10304129995.0 / 1701304382.0,
         -48777925059.0 / 3047939560.0, 15336726248.0 / 1032824649.0,
         -45442868181.0 / 3398467696.0, 3065993473.0 / 597172653.0},
        {185892177.0 / 718116043.0, 0.0, 0.0, -3185094517.0 / 667107341.0,
         -477755414.0 / 1098053517.0, -703635378.0 / 230739211.0, 5731566787.0 / 1027545527.0,
         5232866602.0 / 850066563.0, -4093664535.0 / 808688257.0, 3962137247.0 / 1805957418.0,
         65686358.0 / 487910083.0},
        {403863854.0 / 491063109.0, 0.0, 0.0, -5068492393.0 / 434740067.0,
         -411421997.0 / 543043805.0, 652783627.0 / 914296604.0, 11173962825.0 / 925320556.0,
         -13158990841.0 / 6184727034.0, 3936647629.0 / 1978049680.0, -160528059.0 / 685178525.0,
         248638103.0 / 1413531060.0, 0.0},
    }},
    // b8: 8th-order weights, the solution that is propagated
    {14005451.0 / 335480064.0, 0.0, 0.0, 0.0, 0.0, -59238493.0 / 1068277825.0,
     181606767.0 / 758867731.0, 561292985.0 / 797845732.0, -1041891430.0 / 1371343529.0,
     760417239.0 / 1151165299.0, 118820643.0 / 751138087.0, -528747749.0 / 2220607170.0,
     1.0 / 4.0},
    // b7: embedded 7th-order weights, used only for the error estimate
    {13451932.0 / 455176623.0, 0.0, 0.0, 0.0, 0.0, -808719846.0 / 976000145.0,
     1757004468.0 / 5645159321.0, 656045339.0 / 265891186.0, -3867574721.0 / 1518517206.0,
     465885868.0 / 322736535.0, 53011238.0 / 667516719.0, 2.0 / 45.0, 0.0},
};

// Weights of the error estimate x8 - x7 = h sum_i (b8_i - b7_i) k_i.
constexpr std::array<double, kStages> error_weights() {
  std::array<double, kStages> e{};
  for (int i = 0; i < kStages; ++i) e[i] = kTableau.b8[i] - kTableau.b7[i];
  return e;
}
constexpr std::array<double, kStages> kErrorWeights = error_weights();

// Exponent of the step controller: the estimate is the local error of the 7th-order solution,
// O(h^8), so a step scaled by err^(-1/8) would make err = 1.
constexpr double kControlExponent = -1.0 / 8.0;

// Below ~4 machine epsilons the difference of the two solutions is round-off of x itself and no
// step can meet the tolerance.
constexpr double kSmallestRelativeTolerance = 1e-15;

// The last step may exceed the controller's choice by this fraction to land on t1, rather than
// leave a sliver of an interval for one more (13-evaluation) step.
constexpr double kLandingStretch = 1.01;

std::string at_time(double t) {
  char text[48];
  std::snprintf(text, sizeof text, "t = %.12g s", t);
  return text;
}

std::string seconds(double duration) {
  char text[48];
  std::snprintf(text, sizeof text, "%.6g s", duration);
  return text;
}

// num / den with the limits the error norm needs: 0 / 0 = 0 (nothing to control), x / 0 = inf.
double scaled(double num, double den) {
  if (den > 0.0) return num / den;
  return num == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

// The work arrays of one integrate() call (fixed sizes: nothing is allocated per step).
struct StepWorkspace {
  Eigen::Matrix<double, 6, kStages> k;  // stage derivatives k_i
  Vector6d stage;
  Vector6d increment;
  Vector6d x_new;
  Vector6d difference;
  Vector6d carry = Vector6d::Zero();  // rounding lost by the last update of x (Kahan)
};

// Non-finite t0, t1 or x0, named.
core::Result<bool> check_end_points(double t0, const Vector6d& x0, double t1) {
  if (!std::isfinite(t0)) return core::Error{"t0", "must be finite"};
  if (!std::isfinite(t1)) return core::Error{"t1", "must be finite"};
  if (!x0.allFinite()) return core::Error{"x0", "must be finite"};
  return true;
}

// The 13 stages k_i = f(t + c_i h, x + h sum_j a_ij k_j) of the step from (t, x) to t_new = t + h.
core::Result<bool> evaluate_stages(const Derivative& f, double t, double t_new, double h, const Vector6d& x,
                                   StepWorkspace& w, IntegrationStats& count) {
  for (int i = 0; i < kStages; ++i) {
    // The small increment is summed first and added to x once (one rounding at the scale of x).
    w.increment.setZero();
    for (int j = 0; j < i; ++j) {
      if (kTableau.a[i][j] != 0.0) w.increment.noalias() += (h * kTableau.a[i][j]) * w.k.col(j);
    }
    w.stage = x + w.increment;
    // Stages at c = 1 are evaluated at t_new itself: exactly t1 on the landing step.
    const double t_stage = kTableau.c[i] == 1.0 ? t_new : t + kTableau.c[i] * h;
    w.k.col(i) = f(t_stage, w.stage);
    ++count.evaluations;
    if (!w.k.col(i).allFinite()) {
      return core::Error{"f", "non-finite derivative at " + at_time(t_stage)};
    }
  }
  return true;
}

// The 8th-order solution x_new = x + h sum_i b8_i k_i and the error estimate
// h sum_i (b8_i - b7_i) k_i.
void combine_stages(double h, const Vector6d& x, StepWorkspace& w) {
  w.increment.setZero();
  w.difference.setZero();
  for (int i = 0; i < kStages; ++i) {
    if (kTableau.b8[i] != 0.0) w.increment.noalias() += (h * kTableau.b8[i]) * w.k.col(i);
    if (kErrorWeights[i] != 0.0) w.difference.noalias() += (h * kErrorWeights[i]) * w.k.col(i);
  }
  // Compensated (Kahan) summation of the increments: the low-order bits that x + increment
  // rounds away are carried into the next step instead of being lost. Over 10^4 steps of a LEO
  // orbit this keeps the round-off of |r| ~ 7e6 m from piling up (ulp ~ 1e-9 m per step).
  w.increment += w.carry;
  w.x_new = x + w.increment;
}

// Block-wise mixed error norm: position and velocity each against its own scale.
double error_norm(const Vector6d& x, const StepWorkspace& w, const DormandPrince87Settings& s) {
  const double r_size = std::max(x.head<3>().norm(), w.x_new.head<3>().norm());
  const double v_size = std::max(x.tail<3>().norm(), w.x_new.tail<3>().norm());
  const double scale_r = s.absolute_tolerance + s.relative_tolerance * r_size;
  const double scale_v = s.absolute_tolerance + s.relative_tolerance * v_size;
  return std::max(scaled(w.difference.head<3>().norm(), scale_r), scaled(w.difference.tail<3>().norm(), scale_v));
}

// Next step after an accepted one: h * safety err^(-1/8), at most max_step_growth (no growth
// right after a rejection), within [min_step, max_step].
double step_after_acceptance(double err, double step, bool after_rejection, const DormandPrince87Settings& s) {
  double factor = err > 0.0 ? s.safety_factor * std::pow(err, kControlExponent) : s.max_step_growth;
  factor = std::min(factor, after_rejection ? 1.0 : s.max_step_growth);
  return std::clamp(step * factor, s.min_step_s, s.max_step_s);
}

// Retry after a rejected step of h: shrunk by safety err^(-1/8), at least min_step_shrink (also
// for a non-finite err), never grown, at least min_step.
double step_after_rejection(double err, double h, const DormandPrince87Settings& s) {
  const double factor = std::isfinite(err)
                            ? std::max(s.min_step_shrink, s.safety_factor * std::pow(err, kControlExponent))
                            : s.min_step_shrink;
  return std::max(std::abs(h) * std::min(factor, 1.0), s.min_step_s);
}

}  // namespace

const DormandPrince87Tableau& dormand_prince87_tableau() { return kTableau; }

core::Result<DormandPrince87> DormandPrince87::create(const DormandPrince87Settings& settings) {
  const DormandPrince87Settings& s = settings;
  if (!(s.relative_tolerance == 0.0 ||
        (s.relative_tolerance >= kSmallestRelativeTolerance && s.relative_tolerance < 1.0))) {
    return core::Error{"relative_tolerance", "must be 0 or in [1e-15, 1)"};
  }
  if (!(s.absolute_tolerance >= 0.0) || !std::isfinite(s.absolute_tolerance)) {
    return core::Error{"absolute_tolerance", "must be a finite number >= 0"};
  }
  if (s.relative_tolerance == 0.0 && s.absolute_tolerance == 0.0) {
    return core::Error{"absolute_tolerance", "must be > 0 when relative_tolerance is 0"};
  }
  if (!(s.min_step_s > 0.0) || !std::isfinite(s.min_step_s)) {
    return core::Error{"min_step_s", "must be a finite number > 0 s"};
  }
  if (!(s.max_step_s >= s.min_step_s) || !std::isfinite(s.max_step_s)) {
    return core::Error{"max_step_s", "must be finite and >= min_step_s"};
  }
  if (!(s.initial_step_s >= s.min_step_s && s.initial_step_s <= s.max_step_s)) {
    return core::Error{"initial_step_s", "must be in [min_step_s, max_step_s]"};
  }
  if (s.max_steps <= 0) return core::Error{"max_steps", "must be > 0"};
  if (!(s.safety_factor > 0.0 && s.safety_factor < 1.0)) {
    return core::Error{"safety_factor", "must be in (0, 1)"};
  }
  if (!(s.max_step_growth > 1.0) || !std::isfinite(s.max_step_growth)) {
    return core::Error{"max_step_growth", "must be a finite number > 1"};
  }
  if (!(s.min_step_shrink > 0.0 && s.min_step_shrink < 1.0)) {
    return core::Error{"min_step_shrink", "must be in (0, 1)"};
  }
  return DormandPrince87(settings);
}

core::Result<Vector6d> DormandPrince87::integrate(const Derivative& f, double t0,
                                                  const Vector6d& x0, double t1,
                                                  IntegrationStats* stats) const {
  IntegrationStats unused;
  IntegrationStats& count = stats != nullptr ? *stats : unused;
  count = IntegrationStats{};
  if (auto ok = check_end_points(t0, x0, t1); !ok) return ok.error();
  if (t1 == t0) return x0;

  const DormandPrince87Settings& s = settings_;
  const double direction = t1 > t0 ? 1.0 : -1.0;
  double step = s.initial_step_s;  // magnitude the controller asks for [s]
  bool after_rejection = false;
  double t = t0;
  Vector6d x = x0;
  StepWorkspace w;

  for (;;) {
    if (count.steps_accepted + count.steps_rejected >= s.max_steps) {
      return core::Error{"max_steps", "exceeded (" + std::to_string(s.max_steps) +
                                          " attempted steps) at " + at_time(t)};
    }
    // h is the difference of the two representable end times (exact whenever |h| <= |t|,
    // Sterbenz), so the steps add up to t1 - t0 and the time does not drift from the state.
    const bool landing = std::abs(t1 - t) <= kLandingStretch * step;
    const double t_new = landing ? t1 : t + direction * step;
    const double h = t_new - t;

    if (auto ok = evaluate_stages(f, t, t_new, h, x, w, count); !ok) return ok.error();
    combine_stages(h, x, w);
    const double err = error_norm(x, w, s);

    if (err <= 1.0 && w.x_new.allFinite()) {  // false for a NaN err as well
      ++count.steps_accepted;
      w.carry = w.increment - (w.x_new - x);
      t = t_new;
      x = w.x_new;
      if (landing) return x;
      step = step_after_acceptance(err, step, after_rejection, s);
      after_rejection = false;
    } else {
      ++count.steps_rejected;
      if (std::abs(h) <= s.min_step_s) {
        return core::Error{"min_step_s", "step-size underflow: the local error estimate exceeds the "
                                       "tolerance with a step of " + seconds(std::abs(h)) + " at " +
                                       at_time(t)};
      }
      step = step_after_rejection(err, h, s);
      after_rejection = true;
    }
  }
}

}  // namespace visors::dynamics
