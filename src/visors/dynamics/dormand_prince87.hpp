#pragma once
// Reference (high-accuracy) adaptive integrator: the embedded Runge-Kutta pair RK8(7)13M of
// P. J. Prince and J. R. Dormand, "High order embedded Runge-Kutta formulae", J. Comput. Appl.
// Math. 7(1), 1981, 67-75 (13 stages). The 8th-order solution is propagated (local
// extrapolation); the difference to the embedded 7th-order solution estimates the local error of
// the 7th-order one and drives the step size. Not the DOP853 method of Hairer's codes, which is a
// different 8th-order pair.
//
// Used for the truth trajectories and as the reference against which the on-board RK4
// propagation is judged (dynamics/orbit_propagator.hpp), so accuracy and robustness come before
// speed: every integrate() call either lands exactly on its end time or returns an Error
// (no exception, no endless loop, no NaN returned as a state).

#include <array>
#include <memory>
#include <type_traits>

#include <Eigen/Core>

#include "visors/core/result.hpp"

namespace visors::dynamics {

/// Stacked orbit state [r; v] (position [m], velocity [m/s]) or its derivative [v; a].
using Vector6d = Eigen::Matrix<double, 6, 1>;

/// dx/dt at time t [s since the propagation epoch]: a non-owning, non-allocating reference to any
/// callable `Vector6d(double t, const Vector6d& x)` (the idea of C++26 std::function_ref).
/// It only refers to the callable, so it must not outlive it: pass a lambda or functor directly
/// to integrate() (a temporary lives until the call returns) and never store a Derivative built
/// from a temporary. A plain function is passed by pointer (`&f`).
class Derivative {
 public:
  template <typename F>
    requires(!std::is_same_v<std::remove_cvref_t<F>, Derivative> &&
             std::is_object_v<std::remove_reference_t<F>> &&
             std::is_invocable_r_v<Vector6d, std::remove_reference_t<F>&, double, const Vector6d&>)
  Derivative(F&& f) noexcept  // NOLINT(google-explicit-constructor): implicit on purpose
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_(&invoke<std::remove_reference_t<F>>) {}

  Vector6d operator()(double t, const Vector6d& x) const { return call_(object_, t, x); }

 private:
  template <typename F>
  static Vector6d invoke(void* object, double t, const Vector6d& x) {
    return (*static_cast<F*>(object))(t, x);
  }

  void* object_;
  Vector6d (*call_)(void*, double, const Vector6d&);
};

/// Tunables of the reference integrator; defaults are those of the truth propagation.
///
/// Error norm (see integrate()): position and velocity are judged as 3-vectors, each against
/// absolute_tolerance + relative_tolerance * (its Euclidean norm), so the control does not depend
/// on the orientation of the inertial frame and a coordinate crossing zero does not force tiny
/// steps.
struct DormandPrince87Settings {
  double relative_tolerance = 1e-13;  // per step, of |r| and |v| [-]; 0 or in [1e-15, 1)
  double absolute_tolerance = 1e-9;   // per step, added to the scale: [m] for r, [m/s] for v
  double initial_step_s = 10.0;         // magnitude of the first trial step of each call [s]
  double min_step_s = 1e-6;   // shortest step the controller may choose [s] (the final, landing
                            // step may be shorter); a rejected step at this size is an error
  double max_step_s = 600.0;  // longest step [s]
  int max_steps = 10'000'000;  // attempted (accepted + rejected) steps per integrate() call
  double safety_factor = 0.9;      // h_new = h * safety * err^(-1/8), in (0, 1)
  double max_step_growth = 4.0;    // largest factor h_new / h after an accepted step, > 1
  double min_step_shrink = 0.2;    // smallest factor h_new / h after a rejected step, in (0, 1)
};

struct IntegrationStats {
  long steps_accepted = 0;
  long steps_rejected = 0;
  long evaluations = 0;  // calls of the derivative, rejected steps included
};

/// The coefficients of RK8(7)13M (Prince & Dormand 1981), as doubles: nodes c, the
/// strictly lower-triangular matrix a (a[i][j], j < i), the 8th-order weights b8 (propagated) and
/// the embedded 7th-order weights b7. Exposed so that tests can check the order conditions.
struct DormandPrince87Tableau {
  static constexpr int kStages = 13;
  std::array<double, kStages> c;
  std::array<std::array<double, kStages>, kStages> a;
  std::array<double, kStages> b8;
  std::array<double, kStages> b7;
};
const DormandPrince87Tableau& dormand_prince87_tableau();

class DormandPrince87 {
 public:
  /// Validates the settings; the error names the field ("relative_tolerance", "min_step_s", ...).
  static core::Result<DormandPrince87> create(const DormandPrince87Settings& settings);

  /// Integrates dx/dt = f(t, x) from (t0, x0) to t1 (t1 < t0 integrates backward) and lands
  /// exactly on t1: the last step is cut to end there and the stages at c = 1 of that step are
  /// evaluated at t1 itself. Each call starts again from settings.initial_step_s (no state is kept
  /// between calls, so results do not depend on call history).
  ///
  /// A step is accepted when err <= 1, with err the larger of |dr| / (atol + rtol max(|r_n|,
  /// |r_n+1|)) and the same for v, dr and dv being the difference between the 8th- and 7th-order
  /// solutions. Next step: h * clamp(safety err^(-1/8), min_step_shrink, max_step_growth),
  /// without growth right after a rejection, within [min_step, max_step].
  ///
  /// Errors: non-finite t0 ("t0"), t1 ("t1") or x0 ("x0"); a non-finite derivative ("f"); a step
  /// rejected at min_step_s ("min_step_s", step-size underflow); more than max_steps attempts
  /// ("max_steps"). The message gives the time reached. `stats` (optional) receives the counts of
  /// this call, also when it fails.
  core::Result<Vector6d> integrate(const Derivative& f, double t0, const Vector6d& x0, double t1,
                                   IntegrationStats* stats = nullptr) const;

  [[nodiscard]] const DormandPrince87Settings& settings() const { return settings_; }

 private:
  explicit DormandPrince87(const DormandPrince87Settings& settings) : settings_(settings) {}

  DormandPrince87Settings settings_;
};

}  // namespace visors::dynamics
