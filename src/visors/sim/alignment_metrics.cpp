#include "visors/sim/alignment_metrics.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace visors::sim {

AlignmentSample alignment_sample(const Eigen::Vector3d& p_osc, const Eigen::Vector3d& v_osc, const Eigen::Vector3d& p_dsc,
                                 const Eigen::Vector3d& v_dsc, const Eigen::Vector3d& sun_unit,
                                 const AlignmentRequirements& requirements) {
  const Eigen::Vector3d d = p_osc - p_dsc;
  const Eigen::Vector3d w = v_osc - v_dsc;
  const double along = d.dot(sun_unit);
  return {(d - along * sun_unit).norm(), (w - w.dot(sun_unit) * sun_unit).norm(), along - requirements.focal_distance_m};
}

DetectorAxes detector_axes(const Eigen::Vector3d& sun_unit, const Eigen::Vector3d& dsc_position_gcrf) {
  const Eigen::Vector3d up = dsc_position_gcrf - dsc_position_gcrf.dot(sun_unit) * sun_unit;  // the vertical, normal to the Sun line
  const Eigen::Vector3d x = up.squaredNorm() > 0.0 ? Eigen::Vector3d(up.normalized()) : sun_unit.unitOrthogonal();
  return {x, sun_unit.cross(x), sun_unit};
}

AlignmentSample add_alignment_sample(AlignmentResult& result, const Eigen::Vector3d& p_osc, const Eigen::Vector3d& v_osc,
                                     const Eigen::Vector3d& p_dsc, const Eigen::Vector3d& v_dsc, const Eigen::Vector3d& sun_unit,
                                     const AlignmentRequirements& requirements) {
  const AlignmentSample sample = alignment_sample(p_osc, v_osc, p_dsc, v_dsc, sun_unit, requirements);
  const Eigen::Vector3d d = p_osc - p_dsc;
  const double lateral = sample.lateral_m;
  const double lateral_velocity = sample.lateral_velocity_mps;
  const double focus = std::abs(sample.focus_signed_m);
  if (result.samples == 0 || lateral > result.lateral_error_m) {
    const DetectorAxes axes = detector_axes(sun_unit, p_dsc);
    result.lateral_detector_m = Eigen::Vector2d(d.dot(axes.x), d.dot(axes.y));
  }
  if (result.samples == 0 || focus > result.focus_error_m) result.focus_signed_m = sample.focus_signed_m;
  result.lateral_error_m = std::max(result.lateral_error_m, lateral);
  result.lateral_velocity_mps = std::max(result.lateral_velocity_mps, lateral_velocity);
  result.focus_error_m = std::max(result.focus_error_m, focus);
  ++result.samples;
  return sample;
}

}  // namespace visors::sim
