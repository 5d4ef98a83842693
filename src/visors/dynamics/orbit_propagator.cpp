#include "visors/dynamics/orbit_propagator.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "visors/core/constants.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::dynamics {
namespace {

using core::GpsTime;

constexpr std::int64_t kNs = GpsTime::kNanosecondsPerSecond;

std::int64_t to_nanos(double seconds) { return std::llround(seconds * static_cast<double>(kNs)); }

Vector6d stack(const core::StateVector& x) {
  Vector6d y;
  y << x.r, x.v;
  return y;
}

core::StateVector unstack(const Vector6d& y) { return {y.head<3>(), y.tail<3>()}; }

core::Error state_error(GpsTime t, const std::string& problem) {
  return {"state", problem + " at " + t.format(core::TimeScale::kUtc) + " UTC"};
}

}  // namespace

core::Result<OrbitPropagator> OrbitPropagator::create(ForceModel& forces, const PropagatorSettings& settings) {
  if (!(settings.step_s > 0.0) || !std::isfinite(settings.step_s)) {
    return core::Error{"step_s", "must be a finite number > 0 s"};
  }
  if (!(settings.min_step_s > 0.0) || settings.min_step_s > settings.step_s) {
    return core::Error{"min_step_s", "must be > 0 s and <= step_s"};
  }
  if (settings.step_s * 1e-9 * static_cast<double>(kNs) < 1e-6) {
    return core::Error{"step_s", "must be >= 1 us"};
  }
  OrbitPropagator propagator(forces, settings);
  if (settings.integrator == IntegratorKind::kDormandPrince87) {
    auto reference = DormandPrince87::create(settings.reference);
    if (!reference) return core::Error{"reference." + reference.error().field, reference.error().message};
    propagator.reference_.emplace(std::move(reference).value());
  }
  return propagator;
}

OrbitPropagator::OrbitPropagator(ForceModel& forces, const PropagatorSettings& settings)
    : forces_(&forces), settings_(settings) {}

Vector6d OrbitPropagator::derivative(GpsTime t, const Vector6d& x) {
  ++stats_.evaluations;
  Vector6d dx;
  dx.head<3>() = x.tail<3>();
  dx.tail<3>() = forces_->acceleration(t, unstack(x));
  return dx;
}

// Classical RK4 (Kutta 1901); the force model is evaluated at the sub-step times t + h/2 and
// t + h, so the Earth-fixed gravity field rotates within the step as it should.
Vector6d OrbitPropagator::rk4_step(GpsTime t, const Vector6d& x, std::int64_t h_nanos) {
  const double h = static_cast<double>(h_nanos) / static_cast<double>(kNs);
  const GpsTime t_mid = t + std::chrono::nanoseconds(h_nanos / 2);
  const GpsTime t_end = t + std::chrono::nanoseconds(h_nanos);
  const Vector6d k1 = derivative(t, x);
  const Vector6d k2 = derivative(t_mid, x + 0.5 * h * k1);
  const Vector6d k3 = derivative(t_mid, x + 0.5 * h * k2);
  const Vector6d k4 = derivative(t_end, x + h * k3);
  ++stats_.steps;
  return x + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

core::Result<Vector6d> OrbitPropagator::advance(GpsTime from, const Vector6d& x0, GpsTime to,
                                                GpsTime grid_origin) {
  if (to == from) return x0;
  if (settings_.integrator == IntegratorKind::kDormandPrince87) {
    const auto f = [this, from](double t, const Vector6d& x) { return derivative(from + t, x); };
    IntegrationStats integration;
    auto result = reference_->integrate(f, 0.0, x0, to.seconds_since(from), &integration);
    stats_.steps += integration.steps_accepted;
    if (!result) return state_error(from, "reference integrator failed: " + result.error().message);
    return result;
  }
  const std::int64_t h = to_nanos(settings_.step_s);
  const std::int64_t h_min = to_nanos(settings_.min_step_s);
  Vector6d x = x0;
  GpsTime t = from;
  while (t < to) {
    std::int64_t remaining = to.nanoseconds_since(t);
    std::int64_t dt = 0;
    if (settings_.integrator == IntegratorKind::kRk4Fixed) {
      // Next grid point t0 + k h strictly after t.
      const std::int64_t since = t.nanoseconds_since(grid_origin);
      const std::int64_t to_grid = h - (since % h + h) % h;
      dt = std::min(remaining, to_grid);
    } else if (remaining <= h) {
      dt = remaining;
    } else if (remaining < h + h_min) {
      dt = remaining / 2;
    } else {
      dt = h;
    }
    x = rk4_step(t, x, dt);
    t = t + std::chrono::nanoseconds(dt);
    if (!x.allFinite()) return state_error(t, "non-finite state");
    if (x.head<3>().norm() < forces_->earth_radius() * (1.0 - core::kWgs84Flattening)) {
      return state_error(t, "position below the Earth's surface (|r| = " +
                                std::to_string(x.head<3>().norm()) + " m)");
    }
  }
  return x;
}

core::Result<core::StateVector> OrbitPropagator::propagate(GpsTime t0, const core::StateVector& x0_gcrf,
                                                           std::span<const GpsTime> outputs,
                                                           std::span<const ImpulsiveManeuver> maneuvers,
                                                           const EphemerisCallback& on_output) {
  if (!x0_gcrf.r.allFinite() || !x0_gcrf.v.allFinite()) return core::Error{"state", "not finite"};
  if (x0_gcrf.r.norm() < forces_->earth_radius() * (1.0 - core::kWgs84Flattening)) {
    return core::Error{"state.r", "position is inside the Earth"};
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    if (outputs[k] < t0) return core::Error{"outputs", "time before the initial epoch"};
    if (k > 0 && outputs[k] < outputs[k - 1]) return core::Error{"outputs", "times are not sorted"};
  }
  for (std::size_t k = 0; k < maneuvers.size(); ++k) {
    if (maneuvers[k].t < t0) return core::Error{"maneuvers", "time before the initial epoch"};
    if (k > 0 && maneuvers[k].t < maneuvers[k - 1].t) return core::Error{"maneuvers", "times are not sorted"};
    if (!maneuvers[k].dv.allFinite()) return core::Error{"maneuvers.dv", "not finite"};
  }
  Vector6d x = stack(x0_gcrf);
  GpsTime t = t0;
  std::size_t next_output = 0;
  std::size_t next_maneuver = 0;
  while (next_output < outputs.size()) {
    GpsTime event = outputs[next_output];
    if (next_maneuver < maneuvers.size() && maneuvers[next_maneuver].t < event) {
      event = maneuvers[next_maneuver].t;
    }
    auto advanced = advance(t, x, event, t0);
    if (!advanced) return advanced.error();
    x = advanced.value();
    t = event;
    for (; next_maneuver < maneuvers.size() && maneuvers[next_maneuver].t == t; ++next_maneuver) {
      const ImpulsiveManeuver& burn = maneuvers[next_maneuver];
      const core::StateVector pre = unstack(x);
      x.tail<3>() += burn.frame == ManeuverFrame::kRtn
                         ? Eigen::Vector3d(core::gcrf_to_rtn_matrix(pre).transpose() * burn.dv)
                         : burn.dv;
    }
    for (; next_output < outputs.size() && outputs[next_output] == t; ++next_output) {
      if (on_output) on_output(t, unstack(x));
    }
  }
  return unstack(x);
}

core::Result<core::StateVector> OrbitPropagator::propagate_to(GpsTime t0, const core::StateVector& x0_gcrf,
                                                              GpsTime t1,
                                                              std::span<const ImpulsiveManeuver> maneuvers) {
  const GpsTime outputs[] = {t1};
  return propagate(t0, x0_gcrf, outputs, maneuvers);
}

}  // namespace visors::dynamics
