#include "visors/sim/sky_truth.hpp"

#include <erfa.h>

#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::sim {
namespace {

constexpr double kAuM = 149597870700.0;  // [m] (IAU 2012 B2)
constexpr double kDayS = 86400.0;
constexpr std::int64_t kGridStepNs = static_cast<std::int64_t>(SkyTruth::kGridStepS) * core::GpsTime::kNanosecondsPerSecond;

// Cubic Hermite interpolation of one coordinate on [0, h]: values p0, p1 and rates d0, d1 (per
// second) at the ends; s = elapsed / h. Returns the value and writes the rate.
double hermite(double p0, double d0, double p1, double d1, double h, double s, double& rate) {
  const double s2 = s * s;
  const double s3 = s2 * s;
  rate = ((6.0 * s2 - 6.0 * s) * (p0 - p1) / h + (3.0 * s2 - 4.0 * s + 1.0) * d0 + (3.0 * s2 - 2.0 * s) * d1);
  return (2.0 * s3 - 3.0 * s2 + 1.0) * p0 + (s3 - 2.0 * s2 + s) * h * d0 + (-2.0 * s3 + 3.0 * s2) * p1 +
         (s3 - s2) * h * d1;
}

}  // namespace

SkyTruth::SkyTruth(const Eigen::Vector2d& target_offset_rad) : target_offset_rad_(target_offset_rad) {}

const SkyTruth::Node& SkyTruth::node(std::int64_t k) {
  Node& n = nodes_[static_cast<std::size_t>(((k % 16) + 16) % 16)];
  if (n.index == k) return n;
  n.index = k;
  const core::JulianDate jd = core::GpsTime::from_nanoseconds(k * kGridStepNs).jd_tt();
  double pvh[2][3];
  eraEpv00(jd.jd1, jd.jd2, pvh, n.earth.barycentric_pv);
  for (int i = 0; i < 3; ++i) {
    n.earth.heliocentric_p[i] = pvh[0][i];
    n.earth.heliocentric_v[i] = pvh[1][i];
  }
  return n;
}

SkyTruth::EarthEphemeris SkyTruth::earth(core::GpsTime t) {
  const std::int64_t ns = t.nanoseconds();
  const std::int64_t k = ns >= 0 ? ns / kGridStepNs : -((-ns + kGridStepNs - 1) / kGridStepNs);
  const double s = static_cast<double>(ns - k * kGridStepNs) / static_cast<double>(kGridStepNs);
  const EarthEphemeris& a = node(k).earth;  // k and k + 1 are in different slots
  const EarthEphemeris& b = node(k + 1).earth;
  const double h = kGridStepS / kDayS;  // [d]: the rates are per day
  EarthEphemeris out{};
  for (int i = 0; i < 3; ++i) {
    out.barycentric_pv[0][i] = hermite(a.barycentric_pv[0][i], a.barycentric_pv[1][i], b.barycentric_pv[0][i],
                                       b.barycentric_pv[1][i], h, s, out.barycentric_pv[1][i]);
    out.heliocentric_p[i] = hermite(a.heliocentric_p[i], a.heliocentric_v[i], b.heliocentric_p[i], b.heliocentric_v[i],
                                    h, s, out.heliocentric_v[i]);
  }
  return out;
}

astro::SunView SkyTruth::sun(core::GpsTime t, const core::StateVector& observer_gcrf) {
  EarthEphemeris e = earth(t);  // eraApcs takes non-const arrays
  double pv[2][3];
  for (int i = 0; i < 3; ++i) {
    pv[0][i] = observer_gcrf.r[i];
    pv[1][i] = observer_gcrf.v[i];
  }
  eraASTROM astrom;
  const core::JulianDate jd = t.jd_tt();
  eraApcs(jd.jd1, jd.jd2, pv, e.barycentric_pv, e.heliocentric_p, &astrom);
  // The Sun's barycentric position (= Earth's barycentric - heliocentric) at `at`, from the observer.
  const auto sun_from_observer_au = [&astrom](const EarthEphemeris& at) {
    Eigen::Vector3d d;
    for (int i = 0; i < 3; ++i) d[i] = at.barycentric_pv[0][i] - at.heliocentric_p[i] - astrom.eb[i];
    return d;
  };
  astro::SunView out;
  const Eigen::Vector3d geometric = sun_from_observer_au(e);
  out.distance_m = geometric.norm() * kAuM;
  out.geometric_unit_gcrf = geometric.normalized();
  Eigen::Vector3d emitted = geometric;
  for (int k = 0; k < 3; ++k) emitted = sun_from_observer_au(earth(t - emitted.norm() * kAuM / core::kSpeedOfLight));
  double pnat[3] = {emitted.x() / emitted.norm(), emitted.y() / emitted.norm(), emitted.z() / emitted.norm()};
  double ppr[3];
  eraAb(pnat, astrom.v, astrom.em, astrom.bm1, ppr);
  out.apparent_unit_gcrf = Eigen::Vector3d(ppr[0], ppr[1], ppr[2]).normalized();
  return out;
}

Eigen::Vector3d SkyTruth::target_unit_gcrf(core::GpsTime t, const core::StateVector& observer_gcrf) {
  const astro::SunView view = sun(t, observer_gcrf);
  double v0[3] = {view.apparent_unit_gcrf.x(), view.apparent_unit_gcrf.y(), view.apparent_unit_gcrf.z()};
  double v[3];
  eraTpstv(target_offset_rad_.x(), target_offset_rad_.y(), v0, v);
  return Eigen::Vector3d(v[0], v[1], v[2]).normalized();
}

}  // namespace visors::sim
