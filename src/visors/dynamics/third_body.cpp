#include "visors/dynamics/third_body.hpp"

#include <cmath>

namespace visors::dynamics {

Eigen::Vector3d third_body_acceleration(const Eigen::Vector3d& r, const Eigen::Vector3d& s, double gm) {
  const Eigen::Vector3d d = s - r;
  const double d3 = std::pow(d.squaredNorm(), 1.5);
  const double s3 = std::pow(s.squaredNorm(), 1.5);
  return gm * (d / d3 - s / s3);
}

}  // namespace visors::dynamics
