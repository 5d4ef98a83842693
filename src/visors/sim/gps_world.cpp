#include "visors/sim/gps_world.hpp"

#include "visors/core/earth_frames.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/gnss/constellation.hpp"
#include "visors/gnss/ephemeris_set.hpp"

namespace visors::sim {

core::Result<GpsWorld> load_gps_world(const CampaignScenario& s, double span_s) {
  GpsWorld w;
  const auto path = core::files::find_data_file(s.gnss.nav_file);
  if (!path) return core::Error{"gnss.nav_file", "'" + s.gnss.nav_file + "' not found (nor in the data search path)"};
  auto nav = gnss::files::read_rinex_navigation(*path);
  if (!nav.ok()) return core::Error{"gnss.nav_file", nav.error().describe()};
  w.nav = std::move(nav).value();
  if (s.gnss.receiver.ionosphere && !w.nav.ionosphere) {
    return core::Error{"gnss.nav_file", "has no GPS ionosphere coefficients (needed by gnss.receiver.ionosphere = true)"};
  }
  const auto set = gnss::EphemerisSet::screen(w.nav.records, w.nav.record_lines);
  const auto source = core::GpsTime::parse(s.gnss.source_time_gps, core::TimeScale::kGps);
  if (!source.ok()) return core::Error{"gnss.source_time_gps", source.error().describe()};
  auto constellation = gnss::GpsConstellation::from_broadcast(set, *source, s.t0);
  if (!constellation.ok()) return core::Error{"gnss.nav_file", constellation.error().describe()};
  auto satellites =
      GpsSatelliteTruth::create(*constellation, s.gnss.broadcast_errors, RandomStream(s.seed, "gps.satellites"), span_s);
  if (!satellites.ok()) return core::Error{"gnss.broadcast_errors." + satellites.error().field, satellites.error().message};
  w.satellites.emplace(std::move(satellites).value());
  if (!s.forces.earth_frame.eop.empty()) {
    if (const auto eop_path = core::files::find_data_file(s.forces.earth_frame.eop)) {
      auto table = core::files::read_eop_file(*eop_path);
      if (!table.ok()) return core::Error{"forces.earth_frame.eop", table.error().describe()};
      w.eop.emplace(std::move(table).value());
    }
  }
  return w;
}

namespace {

core::EarthOrientation earth_orientation_at(const GpsWorld& world, core::GpsTime t) {
  core::EarthOrientation eop;
  if (world.eop) {
    if (auto at = world.eop->at(t); at.ok()) eop = *at;
  }
  return eop;
}

}  // namespace

EpochFrame epoch_frame(const GpsWorld& world, core::GpsTime t) {
  const core::EarthOrientation eop = earth_orientation_at(world, t);
  return EpochFrame{core::gcrf_to_itrf_matrix(t, eop), Eigen::Vector3d(0.0, 0.0, core::earth_rotation_rate(eop))};
}

EpochFrame epoch_frame(const GpsWorld& world, core::GpsTime t, core::InterpolatedEarthFrame& earth) {
  const core::EarthOrientation eop = earth_orientation_at(world, t);
  return EpochFrame{earth.gcrf_to_itrf_matrix(t, eop), Eigen::Vector3d(0.0, 0.0, core::earth_rotation_rate(eop))};
}

ReceiverPose receiver_pose(const EpochFrame& frame, core::GpsTime t, const core::StateVector& x_gcrf, const Eigen::Quaterniond& q,
                           const Eigen::Vector3d& omega_gcrf, const Eigen::Vector3d& com_body_m) {
  ReceiverPose pose;
  pose.t = t;
  pose.com_itrf.r = frame.gcrf_to_itrf * x_gcrf.r;
  pose.com_itrf.v = frame.gcrf_to_itrf * x_gcrf.v - frame.omega.cross(pose.com_itrf.r);
  pose.body_to_itrf = frame.gcrf_to_itrf * q.toRotationMatrix();
  pose.com_body_m = com_body_m;
  pose.angular_velocity_itrf = frame.gcrf_to_itrf * omega_gcrf - frame.omega;
  return pose;
}

}  // namespace visors::sim
