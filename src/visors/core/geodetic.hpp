#pragma once
// Geodetic latitude, longitude and height on the WGS-84 ellipsoid (NIMA TR8350.2: a = 6378137 m,
// f = 1/298.257223563), to and from Earth-fixed (ITRF) Cartesian coordinates.
//
// Cartesian -> geodetic: the foot of the normal is the point of the meridian ellipse closest to
// the point, found from the Lagrange-multiplier condition (Eberly, "Distance from a Point to an
// Ellipse, an Ellipsoid, or a Hyperellipsoid", Geometric Tools 2011/2020). With p = sqrt(x^2+y^2)
// and |z| (first quadrant; the sign of z is restored at the end) the closest point is
//   (p_e, z_e) = (a^2 p / (t + a^2), b^2 |z| / (t + b^2)),
// where t > -b^2 is the unique root of the convex, decreasing function
//   F(t) = (a p / (t + a^2))^2 + (b |z| / (t + b^2))^2 - 1.
// t has the sign of the height, and with the normal n = (p / (t + a^2), |z| / (t + b^2)):
//   latitude = atan2(n_z, n_p),   height = t |n|.
// F is solved by Newton's method started below the root (from a lower bound with F >= 0, see the
// .cpp), in the shifted unknown s = t + b^2 so that points near the centre keep full precision:
// on a convex decreasing function the iterates rise monotonically to the root and never
// overshoot, so the method converges from any start, quadratically, and stops when an iterate no
// longer increases: <= 5 iterations from -1000 km to 40 000 km height (measured over 10^5 random
// points), ~10 within 50 km of the centre. Unlike the closed forms (Heikkinen 1982, Vermeille
// 2002), it needs no special branch inside the evolute (within ~43 km of the centre); the two
// degenerate sets are handled exactly:
//   * the polar axis (p = 0): the closest point is the pole, height |z| - b;
//   * the equatorial plane (z = 0): height p - a when p >= (a^2 - b^2)/a (latitude 0); closer to
//     the centre the two nearest points are off the plane and the northern one is returned.
// Accuracy against GeographicLib (tests/core/test_geodetic.cpp): see the test's bounds.

#include <Eigen/Core>

namespace visors::core {

struct GeodeticPosition {
  double latitude = 0.0;   // geodetic latitude [rad], [-pi/2, pi/2]
  double longitude = 0.0;  // [rad], (-pi, pi]; 0 on the polar axis
  double height = 0.0;     // above the WGS-84 ellipsoid along its normal [m]
};

/// Geodetic coordinates of an Earth-fixed position [m] on WGS-84. Defined everywhere (the origin
/// gives latitude pi/2, height -b). Precondition: finite input.
GeodeticPosition geodetic_from_itrf(const Eigen::Vector3d& r_itrf);

/// Earth-fixed position [m] of geodetic coordinates on WGS-84 (closed form:
/// N = a / sqrt(1 - e^2 sin^2 lat), r = ((N + h) cos lat cos lon, (N + h) cos lat sin lon,
/// (N (1 - e^2) + h) sin lat)).
Eigen::Vector3d itrf_from_geodetic(const GeodeticPosition& geodetic);

/// Rotation from Earth-fixed to the local east-north-up frame at `geodetic` (rows: east, north,
/// up = the ellipsoid normal): v_enu = R v_itrf. e = (-sin lon, cos lon, 0),
/// n = (-sin lat cos lon, -sin lat sin lon, cos lat), u = (cos lat cos lon, cos lat sin lon, sin lat).
Eigen::Matrix3d enu_from_itrf_rotation(const GeodeticPosition& geodetic);

}  // namespace visors::core
