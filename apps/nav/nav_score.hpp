#pragma once
// The scores of `visors nav` against the run's truth: per epoch (score) and over the replay
// (summarise: the replay's acceptance figures: time to first fix, errors after it and once
// converged, slips, wrong-fix runs, refix after an outage, NIS, step time).

#include <nlohmann/json.hpp>

#include "visors/nav/cdgps_filter.hpp"
#include "apps/nav/nav_inputs.hpp"
#include "apps/nav/nav_replay.hpp"

namespace visors::nav_app {

/// The relative errors of a solution x (OSC minus DSC) against the truth at t_s [s after the
/// scenario start], in the DSC's RTN frame: centres of mass, antennas (nav_replay.hpp), the
/// payload points along and across the line of sight; the estimate's antennas and payload points
/// in the attitudes the spacecraft know, the truth's in the true ones. valid = false when the
/// truth or the known attitudes have no t_s.
struct RelativeErrors {
  bool valid = false;
  Eigen::Vector3d position_rtn_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_rtn_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d antenna_rtn_m = Eigen::Vector3d::Zero();
  double payload_los_m = 0.0, payload_lateral_m = 0.0;
  Eigen::Matrix3d gcrf_to_rtn = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d c_dsc = Eigen::Matrix3d::Identity(), c_osc = Eigen::Matrix3d::Identity();  // known attitudes
};
RelativeErrors relative_errors(const nav::NavVector& x, const RunInputs& in, double t_s);

/// The antenna phase centre a solution x implies for `craft`, GCRF, at the epoch's time tag: its
/// centre of mass plus the lever the flight software knows (antenna_geometry: calibrated antenna
/// reference point and phase-centre offset, plus the estimated phase-centre error p) in the known
/// attitude, the lever turning with it: r + C l, v + omega x C l (the filter's own model,
/// nav/gps_range_model.hpp phase_centre_lever_gcrf_m).
core::StateVector estimated_antenna(const nav::NavVector& x, nav::Craft craft, const sim::FlightKnowledge& told,
                                    const Eigen::Quaterniond& body_to_gcrf, const Eigen::Vector3d& omega_gcrf_radps);

/// The epoch's errors of the filter's solution (the fixed one when the report applied a fix) at
/// t_s [s after the scenario start], the filter running on `local`.
EpochScore score(const nav::CdgpsFilter& filter, const nav::CdgpsEpochReport& report, const RunInputs& in, double t_s,
                 nav::Craft local);

/// The replay's statistics (nav_command.hpp: the summary's fields).
nlohmann::json summarise(const Replay& replay);

}  // namespace visors::nav_app
