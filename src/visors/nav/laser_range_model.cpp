#include "visors/nav/laser_range_model.hpp"

namespace visors::nav {

MeasurementPrediction predict_laser_range(const NavVector& x, const LaserRangeGeometry& g) {
  const Eigen::Vector3d p_dsc = x.segment<3>(state::position(Craft::kDsc)) + g.dsc_body_to_gcrf * g.dsc_lever_body_m;
  const Eigen::Vector3d p_osc = x.segment<3>(state::position(Craft::kOsc)) + g.osc_body_to_gcrf * g.osc_lever_body_m;
  const Eigen::Vector3d d = p_dsc - p_osc;
  MeasurementPrediction out;
  out.value_m = d.norm() + g.bias_m;
  const Eigen::RowVector3d u = (d / d.norm()).transpose();
  out.h.segment<3>(state::position(Craft::kDsc)) = u;
  out.h.segment<3>(state::position(Craft::kOsc)) = -u;
  return out;
}

}  // namespace visors::nav
