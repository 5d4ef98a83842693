#pragma once
// Position and velocity of one spacecraft in one frame; the frame is named by the variable
// holding it (`chief_gcrf`, `state_itrf`), as everywhere in the project.

#include <Eigen/Core>

namespace visors::core {

struct StateVector {
  Eigen::Vector3d r = Eigen::Vector3d::Zero();  // position [m]
  Eigen::Vector3d v = Eigen::Vector3d::Zero();  // velocity [m/s]
};

}  // namespace visors::core
