#include "sim/alignment_metrics.hpp"

#include <algorithm>
#include <cmath>

namespace visors::sim {

void add_alignment_sample(AlignmentResult& result, const Eigen::Vector3d& p_osc, const Eigen::Vector3d& v_osc,
                          const Eigen::Vector3d& p_dsc, const Eigen::Vector3d& v_dsc, const Eigen::Vector3d& sun_unit,
                          const AlignmentRequirements& requirements) {
  const Eigen::Vector3d d = p_osc - p_dsc;
  const Eigen::Vector3d w = v_osc - v_dsc;
  const double along = d.dot(sun_unit);
  const double lateral = (d - along * sun_unit).norm();
  const double lateral_velocity = (w - w.dot(sun_unit) * sun_unit).norm();
  const double focus = std::abs(along - requirements.focal_distance_m);
  result.lateral_error_m = std::max(result.lateral_error_m, lateral);
  result.lateral_velocity_mps = std::max(result.lateral_velocity_mps, lateral_velocity);
  result.focus_error_m = std::max(result.focus_error_m, focus);
  ++result.samples;
}

}  // namespace visors::sim
