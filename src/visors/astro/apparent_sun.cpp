#include "visors/astro/apparent_sun.hpp"

#include <erfa.h>

#include <cassert>
#include <cmath>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"

namespace visors::astro {
namespace {

constexpr double kAuM = 149597870700.0;  // astronomical unit [m] (IAU 2012 Resolution B2, exact)
constexpr double kDayS = 86400.0;        // [s]

struct BarycentricState {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // [m]
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // [m/s]
};

struct SolarSystemAtT {
  BarycentricState earth;
  BarycentricState sun;
};

// eraEpv00 at t (TT for TDB), in SI units. pvh: Earth heliocentric, pvb: Earth barycentric
// [au, au/d], BCRS (ICRS axes).
SolarSystemAtT solar_system_at(core::GpsTime t) {
  const core::JulianDate jd = t.jd_tt();
  double pvh[2][3];
  double pvb[2][3];
  eraEpv00(jd.jd1, jd.jd2, pvh, pvb);  // status 1 outside 1900-2100: the series still evaluates
  SolarSystemAtT out;
  for (int i = 0; i < 3; ++i) {
    out.earth.r[i] = pvb[0][i] * kAuM;
    out.earth.v[i] = pvb[1][i] * (kAuM / kDayS);
    out.sun.r[i] = (pvb[0][i] - pvh[0][i]) * kAuM;
    out.sun.v[i] = (pvb[1][i] - pvh[1][i]) * (kAuM / kDayS);
  }
  return out;
}

// Special-relativistic aberration of the unit direction p for an observer moving at beta = v/c
// (Kaplan et al. 1989, the aberration step of the apparent-place reduction).
Eigen::Vector3d aberrated(const Eigen::Vector3d& p, const Eigen::Vector3d& beta) {
  const double g = std::sqrt(1.0 - beta.squaredNorm());
  return (g * p + (1.0 + p.dot(beta) / (1.0 + g)) * beta).normalized();
}

}  // namespace

SunView sun_view(core::GpsTime t, const core::StateVector& observer_gcrf) {
  assert(observer_gcrf.r.allFinite() && observer_gcrf.v.allFinite());
  assert(observer_gcrf.v.norm() < core::kSpeedOfLight);
  const SolarSystemAtT ss = solar_system_at(t);
  const Eigen::Vector3d observer_r = ss.earth.r + observer_gcrf.r;  // barycentric [m]
  const Eigen::Vector3d observer_v = ss.earth.v + observer_gcrf.v;  // barycentric [m/s]
  SunView out;
  const Eigen::Vector3d geometric = ss.sun.r - observer_r;
  out.distance_m = geometric.norm();
  out.geometric_unit_gcrf = geometric / out.distance_m;
  // Light time: two fixed-point steps converge to ~1e-11 s (the Sun's radial rate over c is 5e-8).
  double tau = out.distance_m / core::kSpeedOfLight;
  Eigen::Vector3d emitted = geometric;
  for (int k = 0; k < 2; ++k) {
    emitted = ss.sun.r - tau * ss.sun.v - observer_r;
    tau = emitted.norm() / core::kSpeedOfLight;
  }
  out.apparent_unit_gcrf = aberrated(emitted.normalized(), observer_v / core::kSpeedOfLight);
  return out;
}

Eigen::Vector3d offset_on_sky(const Eigen::Vector3d& centre_unit_gcrf, const Eigen::Vector2d& offset_rad) {
  const Eigen::Vector3d east = Eigen::Vector3d::UnitZ().cross(centre_unit_gcrf).normalized();
  const Eigen::Vector3d north = centre_unit_gcrf.cross(east);
  return (centre_unit_gcrf + offset_rad.x() * east + offset_rad.y() * north).normalized();
}

Eigen::Vector3d apparent_target_unit_gcrf(core::GpsTime t, const core::StateVector& observer_gcrf,
                                          const Eigen::Vector2d& offset_rad) {
  return offset_on_sky(sun_view(t, observer_gcrf).apparent_unit_gcrf, offset_rad);
}

}  // namespace visors::astro
