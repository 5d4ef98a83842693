#include "visors/core/earth_frames.hpp"

#include <erfa.h>

#include <cmath>

#include <Eigen/Geometry>

#include "visors/core/constants.hpp"

namespace visors::core {
namespace {

Eigen::Matrix3d to_eigen(const double m[3][3]) {
  Eigen::Matrix3d out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out(i, j) = m[i][j];
  }
  return out;
}

// R3(theta): rotation of the coordinate frame about z by theta (IERS Conventions 2010 ch. 5).
Eigen::Matrix3d r3(double theta) {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  Eigen::Matrix3d m;
  m << c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0;
  return m;
}

// The three factors of r_itrf = W R3(ERA) C r_gcrf and the rotation rate, at one instant.
struct EarthRotation {
  Eigen::Matrix3d c2i;  // C: GCRF -> CIRS
  Eigen::Matrix3d era;  // R3(ERA): CIRS -> TIRS
  Eigen::Matrix3d pom;  // W: TIRS -> ITRF
  double omega;         // [rad/s]
};

Eigen::Matrix3d polar_motion(const JulianDate& tt, const EarthOrientation& eop) {
  double rpom[3][3];
  eraPom00(eop.xp, eop.yp, eraSp00(tt.jd1, tt.jd2), rpom);
  return to_eigen(rpom);
}

EarthRotation full_rotation(GpsTime t, const EarthOrientation& eop) {
  const JulianDate tt = t.jd_tt();
  const JulianDate ut1 = t.jd_ut1(eop.dut1);
  double x = 0.0;
  double y = 0.0;
  double s = 0.0;
  eraXys06a(tt.jd1, tt.jd2, &x, &y, &s);
  // dX, dY are the observed corrections to the IAU 2006/2000A CIP (IERS Conventions 2010 §5.5.4);
  // s is not corrected (its dependence on dX, dY is below 1 uas).
  double rc2i[3][3];
  eraC2ixys(x + eop.dx, y + eop.dy, s, rc2i);
  return {to_eigen(rc2i), r3(eraEra00(ut1.jd1, ut1.jd2)), polar_motion(tt, eop),
          earth_rotation_rate(eop)};
}

StateVector to_itrf(const EarthRotation& e, const StateVector& gcrf) {
  const Eigen::Vector3d omega(0.0, 0.0, e.omega);
  const Eigen::Matrix3d rc2tirs = e.era * e.c2i;
  const Eigen::Vector3d r_tirs = rc2tirs * gcrf.r;
  const Eigen::Vector3d v_tirs = rc2tirs * gcrf.v - omega.cross(r_tirs);
  return {e.pom * r_tirs, e.pom * v_tirs};
}

StateVector to_gcrf(const EarthRotation& e, const StateVector& itrf) {
  const Eigen::Vector3d omega(0.0, 0.0, e.omega);
  const Eigen::Matrix3d rtirs2c = (e.era * e.c2i).transpose();
  const Eigen::Vector3d r_tirs = e.pom.transpose() * itrf.r;
  const Eigen::Vector3d v_tirs = e.pom.transpose() * itrf.v + omega.cross(r_tirs);
  return {rtirs2c * r_tirs, rtirs2c * v_tirs};
}

}  // namespace

double earth_rotation_rate(const EarthOrientation& eop) {
  // IERS Conventions 2010 Table 1.1 nominal rate, scaled by the observed length of day.
  return kEarthRotationRate * (1.0 - eop.lod / kSecondsPerDay);
}

Eigen::Matrix3d gcrf_to_itrf_matrix(GpsTime t, const EarthOrientation& eop) {
  const EarthRotation e = full_rotation(t, eop);
  return e.pom * e.era * e.c2i;
}

StateVector gcrf_to_itrf(GpsTime t, const StateVector& gcrf, const EarthOrientation& eop) {
  return to_itrf(full_rotation(t, eop), gcrf);
}

StateVector itrf_to_gcrf(GpsTime t, const StateVector& itrf, const EarthOrientation& eop) {
  return to_gcrf(full_rotation(t, eop), itrf);
}

// ---------------------------------------------------------------------------------------------
// Interpolated full model

namespace {

Eigen::Vector3d xys06a(GpsTime t) {
  const JulianDate tt = t.jd_tt();
  Eigen::Vector3d out;
  eraXys06a(tt.jd1, tt.jd2, &out(0), &out(1), &out(2));
  return out;
}

}  // namespace

Eigen::Matrix3d InterpolatedEarthFrame::gcrf_to_itrf_matrix(GpsTime t, const EarthOrientation& eop) {
  const double since = t.seconds_since(GpsTime{});
  if (!have_nodes_ || t < node_ || t.seconds_since(node_) > node_interval_s_) {
    node_ = GpsTime{} + std::floor(since / node_interval_s_) * node_interval_s_;
    xys_[0] = xys06a(node_);
    xys_[1] = xys06a(node_ + node_interval_s_);
    have_nodes_ = true;
  }
  const double f = t.seconds_since(node_) / node_interval_s_;
  const Eigen::Vector3d xys = (1.0 - f) * xys_[0] + f * xys_[1];
  double rc2i[3][3];
  eraC2ixys(xys(0) + eop.dx, xys(1) + eop.dy, xys(2), rc2i);
  const JulianDate ut1 = t.jd_ut1(eop.dut1);
  return polar_motion(t.jd_tt(), eop) * r3(eraEra00(ut1.jd1, ut1.jd2)) * to_eigen(rc2i);
}

// ---------------------------------------------------------------------------------------------
// On-board variant

OnboardEarthFrame::OnboardEarthFrame(const EarthOrientation& uplinked, double refresh_interval)
    : eop_(uplinked), refresh_interval_(refresh_interval) {}

void OnboardEarthFrame::set_earth_orientation(const EarthOrientation& uplinked) {
  eop_ = uplinked;
  precession_epoch_.reset();  // W depends on x_p, y_p: rebuild everything at the next call
}

void OnboardEarthFrame::refresh_if_stale(GpsTime t) {
  if (precession_epoch_ &&
      std::abs(t.seconds_since(*precession_epoch_)) <= refresh_interval_) {
    return;
  }
  const JulianDate tt = t.jd_tt();
  // IAU 2000B precession-nutation (77 luni-solar terms, ~1 mas against 2000A; McCarthy & Luzum
  // 2003): the CIP (X, Y) and CIO locator s, held until the next refresh.
  double x = 0.0;
  double y = 0.0;
  double s = 0.0;
  eraXys00b(tt.jd1, tt.jd2, &x, &y, &s);
  double rc2i[3][3];
  eraC2ixys(x, y, s, rc2i);
  c2i_ = to_eigen(rc2i);
  pom_ = polar_motion(tt, eop_);
  precession_epoch_ = t;
}

Eigen::Matrix3d OnboardEarthFrame::gcrf_to_itrf_matrix(GpsTime t) {
  refresh_if_stale(t);
  const JulianDate ut1 = t.jd_ut1(eop_.dut1);
  return pom_ * r3(eraEra00(ut1.jd1, ut1.jd2)) * c2i_;
}

StateVector OnboardEarthFrame::gcrf_to_itrf(GpsTime t, const StateVector& gcrf) {
  refresh_if_stale(t);
  const JulianDate ut1 = t.jd_ut1(eop_.dut1);
  return to_itrf({c2i_, r3(eraEra00(ut1.jd1, ut1.jd2)), pom_, earth_rotation_rate(eop_)}, gcrf);
}

StateVector OnboardEarthFrame::itrf_to_gcrf(GpsTime t, const StateVector& itrf) {
  refresh_if_stale(t);
  const JulianDate ut1 = t.jd_ut1(eop_.dut1);
  return to_gcrf({c2i_, r3(eraEra00(ut1.jd1, ut1.jd2)), pom_, earth_rotation_rate(eop_)}, itrf);
}

}  // namespace visors::core
