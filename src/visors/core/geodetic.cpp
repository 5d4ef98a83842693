#include "visors/core/geodetic.hpp"

#include <algorithm>
#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::core {
namespace {

constexpr double kA = kWgs84SemiMajorAxis;                   // [m]
constexpr double kB = kA * (1.0 - kWgs84Flattening);         // semi-minor axis [m]
constexpr double kA2 = kA * kA;                              // [m^2]
constexpr double kB2 = kB * kB;                              // [m^2]
constexpr double kC2 = kA2 - kB2;                            // linear eccentricity^2 [m^2]
constexpr double kE2 = kWgs84Flattening * (2.0 - kWgs84Flattening);  // first eccentricity^2 [-]
// Newton from below converges in a few iterations outside ~50 km of the centre; the bound only
// guards the slow (x1.5 per step) start for points next to the evolute's cusps.
constexpr int kMaxIterations = 200;

}  // namespace

GeodeticPosition geodetic_from_itrf(const Eigen::Vector3d& r_itrf) {
  const double x = r_itrf.x();
  const double y = r_itrf.y();
  const double z = std::abs(r_itrf.z());
  const double p = std::hypot(x, y);
  const double sign = r_itrf.z() < 0.0 ? -1.0 : 1.0;

  GeodeticPosition g;
  g.longitude = (p == 0.0) ? 0.0 : std::atan2(y, x);
  if (p == 0.0) {  // polar axis: the nearest point is the pole (also for |z| < b)
    g.latitude = sign * kPi / 2.0;
    g.height = z - kB;
    return g;
  }
  if (z == 0.0) {
    if (kA * p >= kC2) {  // outside the evolute: the foot is on the equator
      g.latitude = 0.0;
      g.height = p - kA;
      return g;
    }
    // Inside the evolute on the equatorial plane: t = -b^2 (the F(t) pole), the foot is at
    // p_e = a^2 p / (a^2 - b^2), z_e = b sqrt(1 - (p_e/a)^2); take the northern of the two.
    const double pe = kA2 * p / kC2;
    const double ze = kB * std::sqrt(std::max(0.0, 1.0 - (pe / kA) * (pe / kA)));
    g.latitude = std::atan2(ze / kB2, pe / kA2);
    g.height = -std::hypot(p - pe, ze);
    return g;
  }

  // Newton on F from below (see the header), in the shifted unknown s = t + b^2 > 0, so that the
  // small s of points near the centre (foot near a pole) carries full relative precision:
  //   F(s) = (a p / (s + a^2 - b^2))^2 + (b |z| / s)^2 - 1.
  // Each start value has F >= 0: the first two make one term 1; the third, close to the root at
  // any latitude, follows from s <= s + a^2 - b^2:
  //   F(s) >= (a^2 p^2 + b^2 z^2) / (s + a^2 - b^2)^2 - 1.
  double s = std::max({kA * p - kC2, kB * z, std::hypot(kA * p, kB * z) - kC2});
  for (int k = 0; k < kMaxIterations; ++k) {
    const double u = kA * p / (s + kC2);
    const double w = kB * z / s;
    const double f = u * u + w * w - 1.0;
    if (f <= 0.0) break;  // at the root (to rounding)
    const double df = -2.0 * (u * u / (s + kC2) + w * w / s);
    const double next = s - f / df;
    if (!(next > s)) break;  // converged: no further progress in double precision
    s = next;
  }
  const double np = p / (s + kC2);  // normal direction (unnormalised) [1/m]
  const double nz = z / s;
  g.latitude = sign * std::atan2(nz, np);
  g.height = (s - kB2) * std::hypot(np, nz);  // t |n|
  return g;
}

Eigen::Vector3d itrf_from_geodetic(const GeodeticPosition& geodetic) {
  const double sin_lat = std::sin(geodetic.latitude);
  const double cos_lat = std::cos(geodetic.latitude);
  const double n = kA / std::sqrt(1.0 - kE2 * sin_lat * sin_lat);  // prime-vertical radius [m]
  const double rho = (n + geodetic.height) * cos_lat;
  return {rho * std::cos(geodetic.longitude), rho * std::sin(geodetic.longitude),
          (n * (1.0 - kE2) + geodetic.height) * sin_lat};
}

Eigen::Matrix3d enu_from_itrf_rotation(const GeodeticPosition& geodetic) {
  const double sl = std::sin(geodetic.latitude), cl = std::cos(geodetic.latitude);
  const double so = std::sin(geodetic.longitude), co = std::cos(geodetic.longitude);
  Eigen::Matrix3d r;
  r << -so, co, 0.0,
       -sl * co, -sl * so, cl,
       cl * co, cl * so, sl;
  return r;
}

}  // namespace visors::core
