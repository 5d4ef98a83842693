#pragma once
// GCRF <-> ITRF, position and velocity.
//
// Full model (ground, truth simulation): IAU 2006/2000A, CIO based, through ERFA (IERS
// Conventions 2010 eq. 5.1):  r_itrf = W(t) R3(ERA) C(X+dX, Y+dY, s) r_gcrf, with
//   X, Y, s  eraXys06a(TT) plus the EOP celestial pole offsets dX, dY; C = eraC2ixys;
//   ERA      eraEra00(UT1);  W = eraPom00(x_p, y_p, s'(TT) = eraSp00).
// Velocity (Vallado, Fundamentals of Astrodynamics and Applications, 5th ed., Algorithm 23):
//   v_itrf = W [R3(ERA) C v_gcrf - omega x (R3(ERA) C r_gcrf)],
//   omega = (0, 0, 7.292115146706979e-5 (1 - LOD / 86400 s)) rad/s.
// The neglected rates of C and W are ~3e-12 rad/s (precession), i.e. ~2e-5 m/s at LEO.
//
// On-board model (OnboardEarthFrame): W(x_p, y_p) R3(ERA(UT1)) C(X, Y, s) with the CIP (X, Y)
// and CIO locator s of the IAU 2000B precession-nutation model (eraXys00b: 77 luni-solar
// nutation terms, ~1 mas from 2000A), recomputed together with W only when older than a refresh
// interval (default 600 s); ERA is evaluated at every call. x_p, y_p, UT1-UTC and LOD are
// uplinked constants (their staleness is the operator's error budget, not modelled here).
// Measured error against the full model with the same x_p, y_p, UT1-UTC, LOD, 2024-01..2026-12
// (tests/core/test_earth_frames.cpp: 1500 epochs, each 600 s after a refresh, the worst case):
//   orientation 0.0017" max (bound tested: 0.003")  ->  position 0.055 m max at 6878 km
//   (0.1 m), velocity 6e-5 m/s max (1e-4 m/s).
// Nutation is kept: a bias-precession-only matrix would be off by up to ~10" (330 m), and since
// the precession-nutation matrix is refreshed only every few minutes (a refresh costs ~4 us,
// bench_frames) the per-call cost is the same as without it
// (docs/algorithms/dynamics.md#on-board-earth-frame).

#include <optional>

#include <Eigen/Core>

#include "visors/core/eop.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"

namespace visors::core {

/// Earth's angular velocity including the excess length of day [rad/s].
double earth_rotation_rate(const EarthOrientation& eop);

/// Full IAU 2006/2000A rotation GCRF -> ITRF (apply to column vectors).
Eigen::Matrix3d gcrf_to_itrf_matrix(GpsTime t, const EarthOrientation& eop);
StateVector gcrf_to_itrf(GpsTime t, const StateVector& gcrf, const EarthOrientation& eop);
StateVector itrf_to_gcrf(GpsTime t, const StateVector& itrf, const EarthOrientation& eop);

/// The full model for long ground simulations at a lower cost: the CIP X, Y and the CIO locator s
/// of IAU 2006/2000A evaluated at nodes node_interval_s apart (multiples of it since the GPS
/// epoch) and interpolated linearly between them; ERA and polar motion at every call from the
/// given EOP. The shortest significant nutation terms have periods of days, so at 60 s the
/// interpolation error is ~1e-15 rad (h^2/8 of X''; tested against the full model to 1e-12 rad).
/// The full model costs ~20 us a call (eraXys06a): 6 % of a closed-loop campaign with GPS.
class InterpolatedEarthFrame {
 public:
  explicit InterpolatedEarthFrame(double node_interval_s = 60.0) : node_interval_s_(node_interval_s) {}

  Eigen::Matrix3d gcrf_to_itrf_matrix(GpsTime t, const EarthOrientation& eop);

 private:
  double node_interval_s_;
  bool have_nodes_ = false;
  GpsTime node_;                      // the first node
  Eigen::Vector3d xys_[2];            // X, Y, s at node_ and node_ + interval [rad]
};

/// The cheap on-board transform (see the file comment for its model and error). Not const: the
/// precession-nutation and polar-motion matrices are cached and refreshed when older than the
/// refresh interval.
class OnboardEarthFrame {
 public:
  static constexpr double kDefaultRefreshInterval = 600.0;  // [s]

  /// `uplinked`: x_p, y_p, dut1 (and lod for the velocity); dx, dy are ignored (they are
  /// corrections to IAU 2006/2000A, below the 2000B model's own error). refresh_interval <= 0
  /// recomputes at every call.
  explicit OnboardEarthFrame(const EarthOrientation& uplinked = {},
                             double refresh_interval = kDefaultRefreshInterval);

  /// A new uplink: takes effect at the next call.
  void set_earth_orientation(const EarthOrientation& uplinked);

  Eigen::Matrix3d gcrf_to_itrf_matrix(GpsTime t);
  StateVector gcrf_to_itrf(GpsTime t, const StateVector& gcrf);
  StateVector itrf_to_gcrf(GpsTime t, const StateVector& itrf);

  /// Time at which the cached matrices were computed; empty before the first call.
  [[nodiscard]] std::optional<GpsTime> precession_epoch() const { return precession_epoch_; }

 private:
  void refresh_if_stale(GpsTime t);

  EarthOrientation eop_;
  double refresh_interval_;
  std::optional<GpsTime> precession_epoch_;
  Eigen::Matrix3d c2i_ = Eigen::Matrix3d::Identity();  // GCRF -> CIRS, IAU 2000B
  Eigen::Matrix3d pom_ = Eigen::Matrix3d::Identity();  // TIRS -> ITRF, polar motion W
};

}  // namespace visors::core
