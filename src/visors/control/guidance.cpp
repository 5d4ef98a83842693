#include "visors/control/guidance.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/apparent_sun.hpp"
#include "visors/core/angles.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::control {
namespace {

using astro::RelativeOrbitalElements;
namespace roe = astro::roe;

// Sun elevation beta over the orbit plane and its in-plane angle u_s from the ascending node
// (docs/algorithms/control.md#science-orbit): s_rtn(u) = (cos b cos(u - u_s), -cos b sin(u - u_s),
// sin b).
struct SunGeometry {
  double beta;
  double u_sun;
};

SunGeometry sun_geometry(const astro::KeplerianElements& chief, const Eigen::Vector3d& sun_unit_gcrf) {
  const Eigen::Vector3d node(std::cos(chief.raan), std::sin(chief.raan), 0.0);
  const Eigen::Vector3d normal(std::sin(chief.raan) * std::sin(chief.i), -std::cos(chief.raan) * std::sin(chief.i),
                               std::cos(chief.i));
  const Eigen::Vector3d q = normal.cross(node);
  return {std::asin(std::clamp(sun_unit_gcrf.dot(normal), -1.0, 1.0)),
          std::atan2(sun_unit_gcrf.dot(q), sun_unit_gcrf.dot(node))};
}

}  // namespace

RelativeOrbitalElements standby_roe(double chief_a, const StandbyOrbit& orbit) {
  RelativeOrbitalElements r = RelativeOrbitalElements::Zero();
  const double rho = orbit.separation_m / chief_a;
  r[roe::kDex] = r[roe::kDix] = rho * std::cos(orbit.phase_rad);
  r[roe::kDey] = r[roe::kDiy] = rho * std::sin(orbit.phase_rad);
  return r;
}

core::Outcome<ScienceOrbit> science_orbit(const astro::KeplerianElements& chief_mean_t0, core::GpsTime t0,
                                         const ScienceGeometry& geometry, const core::EarthGravityConstants& gravity) {
  if (const core::Status valid = astro::validate_keplerian(chief_mean_t0).status(); !valid) return valid.within("chief");
  if (!(geometry.focal_distance_m > 0.0) || !std::isfinite(geometry.focal_distance_m)) {
    return core::Status{core::Problem::kOutOfRange, "focal_distance_m", "must be a finite number > 0 m"};
  }
  if (!std::isfinite(geometry.los_rate_mps)) return core::Status{core::Problem::kNotFinite, "los_rate_mps", "must be finite"};
  if (!geometry.offset_rtn_m.allFinite()) return core::Status{core::Problem::kNotFinite, "offset_rtn_m", "must be finite"};

  if (!geometry.target_offset_rad.allFinite()) return core::Status{core::Problem::kNotFinite, "target_offset_rad", "must be finite"};

  // The Sun moves ~1 deg/day: the target's direction at t0 places the observation; the state is
  // then built with its direction at the observation time itself. The apparent direction from the
  // chief (aberration by its velocity): the mean elements' state is within ~10 m/s of the
  // osculating one, 0.007" of aberration.
  const SunGeometry sun0 =
      sun_geometry(chief_mean_t0, astro::apparent_target_unit_gcrf(t0, astro::cartesian_from_keplerian(chief_mean_t0, gravity.mu),
                                                                    geometry.target_offset_rad));
  if (std::abs(sun0.beta) > 89.0 * core::kDegToRad) {
    return core::Status{core::Problem::kOutOfRange, "t0", "the Sun is within 1 deg of the orbit normal: no TN-plane alignment"};
  }
  const double u_obs = core::wrap_two_pi(sun0.u_sun + (geometry.north ? 0.5 : -0.5) * core::kPi);
  const astro::J2SecularRates rates = astro::j2_secular_rates(chief_mean_t0, gravity);
  const double u_rate = rates.argp_dot + rates.M_dot;
  const double u0 = chief_mean_t0.argp + chief_mean_t0.M;
  const double t_obs = core::wrap_two_pi(u_obs - u0) / u_rate;

  ScienceOrbit out;
  out.t_obs = t_obs;
  out.u_obs = u_obs;
  const astro::KeplerianElements chief_obs = astro::propagate_mean_j2(chief_mean_t0, t_obs, gravity);
  const core::StateVector chief_gcrf = astro::cartesian_from_keplerian(chief_obs, gravity.mu);
  const Eigen::Matrix3d to_rtn = core::gcrf_to_rtn_matrix(chief_gcrf);
  const Eigen::Vector3d sun_unit = astro::apparent_target_unit_gcrf(t0 + t_obs, chief_gcrf, geometry.target_offset_rad);
  out.beta = sun_geometry(chief_obs, sun_unit).beta;
  out.sun_rtn = to_rtn * sun_unit;
  // Aligned position; inertial velocity along the Sun line only; its rate in the rotating frame.
  const Eigen::Vector3d r_rtn = geometry.focal_distance_m * out.sun_rtn + geometry.offset_rtn_m;
  const Eigen::Vector3d omega_rtn = to_rtn * core::rtn_angular_velocity_gcrf(chief_gcrf);
  const Eigen::Vector3d v_rtn = geometry.los_rate_mps * out.sun_rtn - omega_rtn.cross(r_rtn);
  out.state_rtn << r_rtn, v_rtn;
  out.roe = astro::roe_from_rtn(chief_obs, out.state_rtn, gravity.mu);
  return out;
}

namespace {

// The transfer's geometry in polar form: e and i magnitudes at both ends, the common phase and
// its change, and the number of legs the step limits need.
struct TransferLegs {
  double rho_e0 = 0.0, rho_i0 = 0.0, rho_e1 = 0.0, rho_i1 = 0.0;
  double phase0 = 0.0, dphase = 0.0;
  int legs = 1;
};

core::Outcome<TransferLegs> transfer_legs(const RelativeOrbitalElements& from, const RelativeOrbitalElements& to,
                                         const TransferSettings& settings) {
  if (!from.allFinite()) return core::Status{core::Problem::kNotFinite, "from", "must be finite"};
  if (!to.allFinite()) return core::Status{core::Problem::kNotFinite, "to", "must be finite"};
  if (!(settings.max_phase_step > 0.0)) return core::Status{core::Problem::kOutOfRange, "max_phase_step", "must be > 0"};
  if (!(settings.max_size_ratio > 1.0)) return core::Status{core::Problem::kOutOfRange, "max_size_ratio", "must be > 1"};
  const auto polar = [](double x, double y) { return Eigen::Vector2d(std::hypot(x, y), std::atan2(y, x)); };
  const Eigen::Vector2d e0 = polar(from[roe::kDex], from[roe::kDey]);
  const Eigen::Vector2d i0 = polar(from[roe::kDix], from[roe::kDiy]);
  const Eigen::Vector2d e1 = polar(to[roe::kDex], to[roe::kDey]);
  const Eigen::Vector2d i1 = polar(to[roe::kDix], to[roe::kDiy]);
  if (e0[0] == 0.0 || i0[0] == 0.0) return core::Status{core::Problem::kSingular, "from", "needs non-zero e and i vectors"};
  if (e1[0] == 0.0 || i1[0] == 0.0) return core::Status{core::Problem::kSingular, "to", "needs non-zero e and i vectors"};
  TransferLegs out;
  out.rho_e0 = e0[0];
  out.rho_i0 = i0[0];
  out.rho_e1 = e1[0];
  out.rho_i1 = i1[0];
  // One common phase: the mean of the e and i phases at each end (they are equal for a parallel
  // configuration; the target's 0.4 deg difference is absorbed by the last leg).
  out.phase0 = e0[1] + 0.5 * std::remainder(i0[1] - e0[1], core::kTwoPi);
  const double phase1 = e1[1] + 0.5 * std::remainder(i1[1] - e1[1], core::kTwoPi);
  out.dphase = std::remainder(phase1 - out.phase0, core::kTwoPi);
  const double log_ratio = std::max(std::abs(std::log(e1[0] / e0[0])), std::abs(std::log(i1[0] / i0[0])));
  out.legs = std::max({1, static_cast<int>(std::ceil(std::abs(out.dphase) / settings.max_phase_step)),
                       static_cast<int>(std::ceil(log_ratio / std::log(settings.max_size_ratio)))});
  return out;
}

void fill_waypoints(std::vector<RelativeOrbitalElements>& waypoints, const RelativeOrbitalElements& from,
                    const RelativeOrbitalElements& to, const TransferLegs& g) {
  for (int k = 1; k < g.legs; ++k) {
    const double f = static_cast<double>(k) / g.legs;
    const double phase = g.phase0 + f * g.dphase;
    const double rho_e = g.rho_e0 * std::pow(g.rho_e1 / g.rho_e0, f);
    const double rho_i = g.rho_i0 * std::pow(g.rho_i1 / g.rho_i0, f);
    RelativeOrbitalElements w = RelativeOrbitalElements::Zero();
    w[roe::kDlambda] = from[roe::kDlambda] + f * (to[roe::kDlambda] - from[roe::kDlambda]);
    w[roe::kDex] = rho_e * std::cos(phase);
    w[roe::kDey] = rho_e * std::sin(phase);
    w[roe::kDix] = rho_i * std::cos(phase);
    w[roe::kDiy] = rho_i * std::sin(phase);
    waypoints.push_back(w);
  }
  waypoints.push_back(to);
}

}  // namespace

core::Result<std::vector<RelativeOrbitalElements>> transfer_waypoints(const RelativeOrbitalElements& from,
                                                                      const RelativeOrbitalElements& to,
                                                                      const TransferSettings& settings) {
  const auto legs = transfer_legs(from, to, settings);
  if (!legs.ok()) return legs.error();
  std::vector<RelativeOrbitalElements> waypoints;
  waypoints.reserve(static_cast<std::size_t>(legs->legs));
  fill_waypoints(waypoints, from, to, *legs);
  return waypoints;
}

core::Outcome<int> transfer_waypoints_into(std::vector<RelativeOrbitalElements>& waypoints,
                                          const RelativeOrbitalElements& from, const RelativeOrbitalElements& to,
                                          const TransferSettings& settings) {
  waypoints.clear();
  const auto legs = transfer_legs(from, to, settings);
  if (!legs.ok()) return legs.status();
  if (static_cast<std::size_t>(legs->legs) > waypoints.capacity()) {
    return core::Status{core::Problem::kCapacity, "waypoints", "more legs than its capacity (a degenerate geometry?)"};
  }
  fill_waypoints(waypoints, from, to, *legs);
  return legs->legs;
}

}  // namespace visors::control
