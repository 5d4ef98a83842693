// WGS-84 geodetic coordinates: against GeographicLib's Geocentric (Karney; Vermeille's closed
// form with its inside-the-evolute extension), an independent implementation, plus the exact
// special sets (poles, equator, origin region).
#include <gtest/gtest.h>

#include <GeographicLib/Geocentric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <utility>
#include <vector>

#include "visors/core/constants.hpp"
#include "visors/core/geodetic.hpp"

namespace {

using visors::core::GeodeticPosition;
using visors::core::geodetic_from_itrf;
using visors::core::itrf_from_geodetic;
using visors::core::enu_from_itrf_rotation;
using visors::core::kDegToRad;
using visors::core::kPi;

constexpr double kA = visors::core::kWgs84SemiMajorAxis;
constexpr double kB = kA * (1.0 - visors::core::kWgs84Flattening);

struct Reference {
  double latitude;   // [rad]
  double longitude;  // [rad]
  double height;     // [m]
};

Reference geographiclib_reverse(const Eigen::Vector3d& r) {
  double lat = 0.0;
  double lon = 0.0;
  double h = 0.0;
  GeographicLib::Geocentric::WGS84().Reverse(r.x(), r.y(), r.z(), lat, lon, h);
  return {lat * kDegToRad, lon * kDegToRad, h};
}

Eigen::Vector3d geographiclib_forward(double lat_rad, double lon_rad, double h) {
  Eigen::Vector3d r;
  GeographicLib::Geocentric::WGS84().Forward(lat_rad / kDegToRad, lon_rad / kDegToRad, h, r.x(),
                                             r.y(), r.z());
  return r;
}

// 20000 random points, latitude uniform in sin, longitude uniform, height uniform in
// [-1000 km, 40 000 km]; the Cartesian point is GeographicLib's.
class RandomPoints : public ::testing::Test {
 protected:
  void SetUp() override {
    std::mt19937_64 rng(20241001);
    std::uniform_real_distribution<double> sin_lat(-1.0, 1.0);
    std::uniform_real_distribution<double> lon(-kPi, kPi);
    std::uniform_real_distribution<double> h(-1.0e6, 4.0e7);
    for (int k = 0; k < 20000; ++k) {
      const double lat_k = std::asin(sin_lat(rng));
      const double lon_k = lon(rng);
      const double h_k = h(rng);
      points_.push_back({lat_k, lon_k, h_k});
    }
  }
  std::vector<Reference> points_;
};

TEST_F(RandomPoints, GeodeticFromItrfMatchesGeographicLib) {
  double dh = 0.0;
  double dlat = 0.0;
  double dlon = 0.0;
  for (const Reference& p : points_) {
    const Eigen::Vector3d r = geographiclib_forward(p.latitude, p.longitude, p.height);
    const Reference ref = geographiclib_reverse(r);
    const GeodeticPosition g = geodetic_from_itrf(r);
    dh = std::max(dh, std::abs(g.height - ref.height));
    dlat = std::max(dlat, std::abs(g.latitude - ref.latitude));
    dlon = std::max(dlon, std::abs(std::remainder(g.longitude - ref.longitude, 2.0 * kPi)));
  }
  std::cout << "[ measured ] max |dh| " << dh << " m, |dlat| " << dlat << " rad, |dlon| " << dlon
            << " rad\n";
  // Bounds: a few ulp of |r| <= 4.7e7 m (ulp 7.5e-9 m); 2e-15 rad = 0.1 nm at 46 000 km.
  EXPECT_LT(dh, 5e-8);
  EXPECT_LT(dlat, 2e-15);
  EXPECT_LT(dlon, 1e-15);
}

TEST_F(RandomPoints, ItrfFromGeodeticMatchesGeographicLib) {
  double dr = 0.0;
  for (const Reference& p : points_) {
    const Eigen::Vector3d ref = geographiclib_forward(p.latitude, p.longitude, p.height);
    const Eigen::Vector3d r = itrf_from_geodetic({p.latitude, p.longitude, p.height});
    dr = std::max(dr, (r - ref).norm());
  }
  std::cout << "[ measured ] max |dr| " << dr << " m\n";
  EXPECT_LT(dr, 5e-8);  // a few ulp of |r| (GeographicLib converts degrees, exact at the ulp level)
}

TEST_F(RandomPoints, RoundTripIsExactToRounding) {
  double dr = 0.0;
  for (const Reference& p : points_) {
    const Eigen::Vector3d r = itrf_from_geodetic({p.latitude, p.longitude, p.height});
    dr = std::max(dr, (itrf_from_geodetic(geodetic_from_itrf(r)) - r).norm());
  }
  std::cout << "[ measured ] round trip max |dr| " << dr << " m\n";
  // round-off: a few ulp of |r| <= 4.7e7 m (ulp 7.5e-9 m); measured 1.7e-8 m (2026-11)
  EXPECT_LT(dr, 5e-8);
}

TEST(Geodetic, NorthPoleIsExact) {
  const GeodeticPosition g = geodetic_from_itrf({0.0, 0.0, kB + 500e3});
  EXPECT_EQ(g.latitude, kPi / 2.0);
  EXPECT_EQ(g.longitude, 0.0);
  EXPECT_NEAR(g.height, 500e3, 1e-9);  // (b + h) - b, one rounding of b + h
}

TEST(Geodetic, SouthPoleIsExact) {
  const GeodeticPosition g = geodetic_from_itrf({0.0, 0.0, -(kB + 500e3)});
  EXPECT_EQ(g.latitude, -kPi / 2.0);
  // round-off: one rounding of b + h (ulp 9.3e-10 m); measured 0 (2026-11)
  EXPECT_NEAR(g.height, 500e3, 1e-9);
}

TEST(Geodetic, NearPoleMatchesGeographicLib) {
  // 1 mm off the axis: the normal is still well defined and the height continuous.
  const Eigen::Vector3d r(1e-3, 0.0, kB + 500e3);
  const Reference ref = geographiclib_reverse(r);
  const GeodeticPosition g = geodetic_from_itrf(r);
  // round-off: ~10 ulp of |r| = 6.9e6 m (ulp 9.3e-10 m); measured 5.8e-11 m (2026-11). Latitude: a few ulp of pi/2, measured 0
  EXPECT_NEAR(g.height, ref.height, 1e-8);
  EXPECT_NEAR(g.latitude, ref.latitude, 1e-15);
}

TEST(Geodetic, EquatorIsExact) {
  const GeodeticPosition g = geodetic_from_itrf({0.0, kA + 500e3, 0.0});
  EXPECT_EQ(g.latitude, 0.0);
  EXPECT_EQ(g.longitude, kPi / 2.0);
  EXPECT_EQ(g.height, 500e3);  // a + 500 km is an integer: exact
}

TEST(Geodetic, OriginRegionMatchesGeographicLib) {
  // Inside the evolute (< ~43 km from the centre), including the equatorial plane and the axis.
  double dh = 0.0;
  double dlat = 0.0;
  for (double p : {0.0, 1.0, 1e3, 2e4, 4e4, 4.2e4, 5e4}) {
    for (double z : {1e-3, 1.0, 100.0, 1e3, 1e4, 3e4}) {
      const Eigen::Vector3d r(p, 0.0, z);
      const Reference ref = geographiclib_reverse(r);
      const GeodeticPosition g = geodetic_from_itrf(r);
      dh = std::max(dh, std::abs(g.height - ref.height));
      dlat = std::max(dlat, std::abs(g.latitude - ref.latitude));
    }
  }
  std::cout << "[ measured ] origin region max |dh| " << dh << " m, |dlat| " << dlat << " rad\n";
  // round-off: ~10 ulp of |h| <= 6.4e6 m (ulp 9.3e-10 m) and a few ulp of pi/2; measured 1.9e-9 m, 3.9e-16 rad (2026-11)
  EXPECT_LT(dh, 1e-8);
  EXPECT_LT(dlat, 2e-15);
}

TEST(Geodetic, EquatorialPlaneInsideEvoluteMatchesGeographicLib) {
  for (double p : {1.0, 1e3, 2e4, 4e4}) {
    const Eigen::Vector3d r(p, 0.0, 0.0);
    const Reference ref = geographiclib_reverse(r);
    const GeodeticPosition g = geodetic_from_itrf(r);
    // round-off: ~10 ulp of |h| (9.3e-10 m): measured 9.3e-10 m (2026-11). Latitude: loose, measured 5e-16 rad, bound 1e-12 ~2000x above
    EXPECT_NEAR(g.height, ref.height, 1e-8) << "p = " << p;
    EXPECT_NEAR(std::abs(g.latitude), std::abs(ref.latitude), 1e-12) << "p = " << p;
  }
}

TEST(Geodetic, OriginIsThePole) {
  const GeodeticPosition g = geodetic_from_itrf(Eigen::Vector3d::Zero());
  EXPECT_EQ(g.latitude, kPi / 2.0);
  EXPECT_EQ(g.height, -kB);
}

}  // namespace

// The local east-north-up rotation against GeographicLib's Geocentric::Forward rotation matrix M
// (Karney; M's columns are the local east, north, up axes in Earth-fixed coordinates), at the GSI
// base station 3040 (Japan) and at a southern, western point.
TEST(Geodetic, EnuRotationMatchesGeographicLib) {
  for (const auto& [lat_deg, lon_deg] : {std::pair{35.15, 139.6}, std::pair{-33.9, -70.7}}) {
    std::vector<double> m(9);
    double x = 0.0, y = 0.0, z = 0.0;
    GeographicLib::Geocentric::WGS84().Forward(lat_deg, lon_deg, 0.0, x, y, z, m);
    const Eigen::Matrix3d r = enu_from_itrf_rotation({lat_deg * kDegToRad, lon_deg * kDegToRad, 0.0});
    for (int row = 0; row < 3; ++row) {
      for (int col = 0; col < 3; ++col) {
        EXPECT_NEAR(r(row, col), m[static_cast<std::size_t>(3 * col + row)], 1e-15) << row << "," << col;
      }
    }
  }
}
