#pragma once
// Observation alignment metrics (Guffanti et al., AAS 23-149, 2023, sec. 2;
// docs/requirements.md#science-alignment-requirements), from the TRUE positions and velocities of
// the payload reference points (photon-sieve centre on the OSC, detector aperture centre on the
// DSC) over the observation window. With s the unit apparent direction of the commanded target
// from the DSC (sim/sky_truth.hpp: light time, aberration by the DSC's velocity, the offset on the
// solar disc), d = p_OSC - p_DSC and w = v_OSC - v_DSC (inertial):
//   lateral error     |d - (d.s) s|        <= 18 mm
//   focus error       | d.s - 40 m |       <= 15 mm
//   lateral velocity  |w - (w.s) s|        <= 0.2 mm/s
// each taken as its worst value over the window; the attempt succeeds when all three hold for
// the whole window.

#include <Eigen/Core>

namespace visors::sim {

struct AlignmentRequirements {
  double lateral_error_m = 0.018;
  double lateral_velocity_mps = 2e-4;
  double focus_error_m = 0.015;
  double focal_distance_m = 40.0;
};

struct AlignmentResult {
  int index = 0;
  double t_s = 0.0;  // window start since t0 [s]
  double lateral_error_m = 0.0;
  double lateral_velocity_mps = 0.0;
  double focus_error_m = 0.0;
  /// At the worst lateral sample, the lateral error in the detector's frame [m]: z towards the
  /// Sun, x the local vertical (the DSC's radial direction) projected normal to z, y = z x x.
  Eigen::Vector2d lateral_detector_m = Eigen::Vector2d::Zero();
  double focus_signed_m = 0.0;  // at the worst focus sample, separation along z minus focal distance [m]
  /// Worst angle over the window between each spacecraft's true payload line of sight and the
  /// target's apparent direction (DSC, OSC) [rad]: the field of view, not part of the score.
  Eigen::Vector2d payload_pointing_rad = Eigen::Vector2d::Zero();
  int samples = 0;
  [[nodiscard]] bool success(const AlignmentRequirements& req) const {
    return samples > 0 && lateral_error_m <= req.lateral_error_m && lateral_velocity_mps <= req.lateral_velocity_mps &&
           focus_error_m <= req.focus_error_m;
  }
};

/// One sample's values: lateral and lateral-velocity errors [m, m/s] and the signed separation
/// along the line of sight minus the focal distance [m].
struct AlignmentSample {
  double lateral_m = 0.0;
  double lateral_velocity_mps = 0.0;
  double focus_signed_m = 0.0;
};

/// The detector's frame of a sample: z the target's apparent direction `sun_unit`, x the DSC's
/// radial direction projected normal to z (any normal when degenerate), y = z x x (unit, GCRF).
struct DetectorAxes {
  Eigen::Vector3d x, y, z;
};
DetectorAxes detector_axes(const Eigen::Vector3d& sun_unit, const Eigen::Vector3d& dsc_position_gcrf);

/// The sample of payload points p, their inertial velocities v (GCRF [m], [m/s]) and the target's
/// apparent unit direction from the DSC (the file comment's formulas).
AlignmentSample alignment_sample(const Eigen::Vector3d& p_osc, const Eigen::Vector3d& v_osc, const Eigen::Vector3d& p_dsc,
                                 const Eigen::Vector3d& v_dsc, const Eigen::Vector3d& sun_unit,
                                 const AlignmentRequirements& requirements);

/// Folds one sample of the window into `result` (worst values) and returns it. Positions [m], velocities [m/s],
/// GCRF; sun_unit: the target's apparent direction from the DSC.
AlignmentSample add_alignment_sample(AlignmentResult& result, const Eigen::Vector3d& p_osc, const Eigen::Vector3d& v_osc,
                          const Eigen::Vector3d& p_dsc, const Eigen::Vector3d& v_dsc, const Eigen::Vector3d& sun_unit,
                          const AlignmentRequirements& requirements);

}  // namespace visors::sim
