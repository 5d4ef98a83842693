#pragma once
// The truth's sky: the apparent Sun and the apparent observation target seen from a spacecraft,
// computed with ERFA's astrometry functions, independently of the flight software's
// astro/apparent_sun.hpp (which the score must not trust):
//   ephemeris   eraEpv00 (the Earth's barycentric and heliocentric state), evaluated on a 60 s
//               grid and interpolated by cubic Hermite polynomials in position and velocity (the
//               interpolation differs from the series by < 1 cm: tests/sim/test_sky_truth.cpp; one series
//               evaluation costs ~15 us, a step of the campaign needs several);
//   light time  the Sun's barycentric position at the emission time t - tau itself (iterated);
//   aberration  eraApcs (the observer's barycentric position and velocity) and eraAb (relativistic
//               aberration with the Sun's gravitational term);
//   target      eraTpstv: the standard coordinates (xi east, eta north) of the commanded target
//               about the apparent Sun centre.
// The flight code shares only the ephemeris series (eraEpv00, 0.006" worst case against DE405:
// 1 um at 40 m); every correction is computed another way.
//
// Not thread-safe: the ephemeris grid is a cache (fixed size, nothing allocated after creation).

#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "visors/astro/apparent_sun.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"

namespace visors::sim {

class SkyTruth {
 public:
  /// `target_offset_rad`: the commanded target's standard coordinates about the apparent Sun
  /// centre, (xi towards the east, eta towards the north celestial pole) [rad].
  explicit SkyTruth(const Eigen::Vector2d& target_offset_rad = Eigen::Vector2d::Zero());

  /// The Sun's centre seen at `t` by an observer with geocentric GCRF state `observer_gcrf`.
  [[nodiscard]] astro::SunView sun(core::GpsTime t, const core::StateVector& observer_gcrf);
  /// The apparent unit direction of the target from the observer (GCRF).
  [[nodiscard]] Eigen::Vector3d target_unit_gcrf(core::GpsTime t, const core::StateVector& observer_gcrf);

  /// The Earth's barycentric state and heliocentric position at `t` [au, au/d], interpolated on
  /// the grid (exposed for the interpolation test).
  struct EarthEphemeris {
    double barycentric_pv[2][3];
    double heliocentric_p[3];
    double heliocentric_v[3];
  };
  [[nodiscard]] EarthEphemeris earth(core::GpsTime t);

  static constexpr double kGridStepS = 60.0;

 private:
  struct Node {
    std::int64_t index = INT64_MIN;  // grid node k: GPS time k * kGridStepS
    EarthEphemeris earth{};          // at the node
  };
  const Node& node(std::int64_t k);

  // Slot k mod 16: the nodes around t (k, k + 1) and around the emission time t - 499 s
  // (k - 9, k - 8) never share a slot.
  std::array<Node, 16> nodes_{};
  Eigen::Vector2d target_offset_rad_;
};

}  // namespace visors::sim
