#pragma once
// The GPS part of the truth world, shared by `visors gnss-sim` and `visors run`: the
// constellation of [gnss] nav_file moved to the scenario start with its broadcast errors
// (sim/gps_satellite_truth.hpp), the navigation file's Klobuchar coefficients (the truth
// ionosphere), the Earth orientation of the truth (the force model's EOP file when it names one,
// else zero EOP), and the pose a receiver needs from a spacecraft's truth.

#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/gps_receiver.hpp"
#include "visors/sim/gps_satellite_truth.hpp"

namespace visors::sim {

struct GpsWorld {
  gnss::files::NavigationFile nav;
  std::optional<GpsSatelliteTruth> satellites;
  std::optional<core::EopTable> eop;
};

/// Reads [gnss] nav_file and draws the broadcast errors of the data sets covering span_s seconds
/// (RandomStream(seed, "gps.satellites")). Errors name the field (gnss.nav_file,
/// gnss.source_time_gps, gnss.broadcast_errors.*, forces.earth_frame.eop).
core::Result<GpsWorld> load_gps_world(const CampaignScenario& scenario, double span_s);

/// The Earth's orientation at one epoch, common to both spacecraft.
struct EpochFrame {
  Eigen::Matrix3d gcrf_to_itrf = Eigen::Matrix3d::Identity();
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();  // Earth rotation in ITRF [rad/s]
};
EpochFrame epoch_frame(const GpsWorld& world, core::GpsTime t);
/// The same with the interpolated full model (core::InterpolatedEarthFrame: 6e-15 rad from it),
/// for the closed loop's every step.
EpochFrame epoch_frame(const GpsWorld& world, core::GpsTime t, core::InterpolatedEarthFrame& earth);

/// The body's angular velocity (GCRF axes) [rad/s] of the attitude law `at(t_s, r, v)` (body to
/// GCRF) about a state x at t_s: the rotation between the attitudes at t_s -/+ 0.5 s, the states
/// there from the two-body motion, divided by 1 s (truncation ~ (w h)^2 of ~1e-3 rad/s in the
/// tracking; exact for a constant-rate eigen-axis slew except within 0.5 s of its start and end).
template <class AttitudeLaw>
Eigen::Vector3d attitude_rate_gcrf(const AttitudeLaw& at, double t_s, const core::StateVector& x) {
  constexpr double h = 0.5;
  const Eigen::Vector3d a = -core::EarthGravityConstants{}.mu / std::pow(x.r.norm(), 3) * x.r;
  const Eigen::Quaterniond before = at(t_s - h, Eigen::Vector3d(x.r - h * x.v + 0.5 * h * h * a), Eigen::Vector3d(x.v - h * a));
  const Eigen::Quaterniond after = at(t_s + h, Eigen::Vector3d(x.r + h * x.v + 0.5 * h * h * a), Eigen::Vector3d(x.v + h * a));
  const Eigen::AngleAxisd turn(after * before.conjugate());  // about GCRF axes
  return turn.angle() / (2.0 * h) * turn.axis();
}

/// The receiver's pose at t from the spacecraft's true state (GCRF), attitude (body to GCRF),
/// its angular velocity (GCRF) and the true centre of mass in the body frame.
ReceiverPose receiver_pose(const EpochFrame& frame, core::GpsTime t, const core::StateVector& x_gcrf, const Eigen::Quaterniond& q,
                           const Eigen::Vector3d& omega_gcrf, const Eigen::Vector3d& com_body_m);

}  // namespace visors::sim
