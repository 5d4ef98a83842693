#pragma once
// A small truth world for the GPS receiver tests: the mission-epoch constellation (moved from the
// 2024 NYA1 navigation file), its broadcast errors, and receiver poses on a circular 500 km,
// 97.4 deg orbit in a simplified Earth frame (the inertial frame rotated at the GPS Earth rate
// about z from the mission epoch: exact enough for measurement geometry tests). Also used by
// bench/bench_gnss.cpp, so it does not depend on GoogleTest.

#include <cmath>
#include <memory>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "visors/core/constants.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/gnss/constellation.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/sim/gps_receiver.hpp"
#include "visors/sim/gps_satellite_truth.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::test {

inline const core::GpsTime kMissionEpoch = core::GpsTime::from_week_seconds(2334, 172800.0).value();  // 2024-10-01

inline constexpr const char* kMissionNavFile = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";

/// Whether the navigation file of the mission constellation is in the data search path (tests
/// skip without it, data/SOURCES.md).
inline bool have_mission_nav() { return core::files::find_data_file(kMissionNavFile).has_value(); }

inline gnss::GpsConstellation mission_constellation() {
  const auto path = core::files::find_data_file(kMissionNavFile);
  if (!path) throw std::runtime_error("gnss/NYA100NOR_S_20241280000_01D_GN.rnx not in the data search path");
  const auto nav = gnss::files::read_rinex_navigation(*path);
  if (!nav.ok()) throw std::runtime_error(nav.error().describe());
  const auto set = gnss::EphemerisSet::screen(nav->records, nav->record_lines);
  return gnss::GpsConstellation::from_broadcast(set, core::GpsTime::from_week_seconds(2313, 2 * 86400.0 + 43200.0).value(),
                                                kMissionEpoch)
      .value();
}

/// Circular orbit, radius 6878.137 km, inclination 97.4 deg, RAAN 0, argument of latitude
/// u0 + n t; `along_offset_m` moves the spacecraft along the orbit (a second spacecraft 40 m ahead).
struct CircularOrbit {
  double radius_m = core::kWgs84SemiMajorAxis + 500e3;
  double inclination_rad = 97.4 * core::kDegToRad;
  double u0_rad = 0.3;
  double raan_rad = 0.0;
  double along_offset_m = 0.0;

  [[nodiscard]] core::StateVector inertial(double t_s) const {
    const double n = std::sqrt(gnss::kGpsMu / (radius_m * radius_m * radius_m));
    const double u = u0_rad + n * t_s + along_offset_m / radius_m;
    const Eigen::Matrix3d plane = (Eigen::AngleAxisd(raan_rad, Eigen::Vector3d::UnitZ()) *
                                   Eigen::AngleAxisd(inclination_rad, Eigen::Vector3d::UnitX()))
                                      .toRotationMatrix();
    return {plane * Eigen::Vector3d(radius_m * std::cos(u), radius_m * std::sin(u), 0.0),
            plane * Eigen::Vector3d(-radius_m * n * std::sin(u), radius_m * n * std::cos(u), 0.0)};
  }
};

/// Inertial -> Earth-fixed at t_s after the epoch: a rotation by w_E t about z.
inline Eigen::Matrix3d inertial_to_earth(double t_s) {
  return Eigen::AngleAxisd(-gnss::kGpsEarthRate * t_s, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

/// The pose for a given body-to-inertial attitude and the body's inertial angular velocity
/// (inertial axes; zero: an inertially fixed attitude).
inline sim::ReceiverPose pose_with_attitude(const CircularOrbit& orbit, double t_s, const Eigen::Matrix3d& body_to_inertial,
                                            const Eigen::Vector3d& omega_inertial = Eigen::Vector3d::Zero()) {
  const core::StateVector x = orbit.inertial(t_s);
  const Eigen::Matrix3d to_earth = inertial_to_earth(t_s);
  const Eigen::Vector3d omega(0.0, 0.0, gnss::kGpsEarthRate);
  sim::ReceiverPose p;
  p.t = kMissionEpoch + t_s;
  p.com_itrf = {to_earth * x.r, to_earth * (x.v - omega.cross(x.r))};
  p.body_to_itrf = to_earth * body_to_inertial;
  p.angular_velocity_itrf = to_earth * (omega_inertial - omega);  // relative to the Earth, Earth-fixed axes
  return p;
}

/// Body axes: +Z (antenna) along the zenith, +X along the velocity; `tilt_rad` about body X. The
/// body turns with the orbit: angular velocity r x v / |r|^2 (exact on the circular orbit).
inline sim::ReceiverPose pose(const CircularOrbit& orbit, double t_s, double tilt_rad = 0.0) {
  const core::StateVector x = orbit.inertial(t_s);
  const Eigen::Vector3d z = x.r.normalized();
  const Eigen::Vector3d y = z.cross(x.v).normalized();
  Eigen::Matrix3d body_to_inertial;
  body_to_inertial << y.cross(z), y, z;
  return pose_with_attitude(orbit, t_s, body_to_inertial * Eigen::AngleAxisd(tilt_rad, Eigen::Vector3d::UnitX()).toRotationMatrix(),
                            x.r.cross(x.v) / x.r.squaredNorm());
}

/// The ionosphere of the 2024 NYA1 file's header (GPSA / GPSB).
inline gnss::KlobucharCoefficients nya_klobuchar() {
  return {{2.5146e-08, 1.4901e-08, -1.1921e-07, -5.9605e-08}, {1.2902e+05, 8.1920e+04, -2.6214e+05, 1.9661e+05}};
}


/// The fixture of the receiver tests: the mission constellation and the satellites' truth, made
/// once per suite (skipped without the shared navigation file), and a receiver factory.
class GpsReceiverWorld : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_mission_nav()) return;
    constellation_ = std::make_unique<gnss::GpsConstellation>(mission_constellation());
    truth_ = std::make_unique<sim::GpsSatelliteTruth>(
        sim::GpsSatelliteTruth::create(*constellation_, {}, sim::RandomStream(7, "gps.satellites")).value());
  }
  static void TearDownTestSuite() {
    truth_.reset();
    constellation_.reset();
  }
  void SetUp() override {
    if (!have_mission_nav()) GTEST_FAIL() << kMissionNavFile << " not found: set VISORS_DATA_PATH";
  }
  static sim::GpsReceiverSettings settings() {
    sim::GpsReceiverSettings s;
    s.klobuchar = nya_klobuchar();
    return s;
  }
  static sim::GpsReceiver receiver(const sim::GpsReceiverSettings& s, const char* name) {
    return sim::GpsReceiver::create(s, sim::RandomStream(11, name)).value();
  }
  static inline std::unique_ptr<gnss::GpsConstellation> constellation_;
  static inline std::unique_ptr<sim::GpsSatelliteTruth> truth_;
};

}  // namespace visors::test
