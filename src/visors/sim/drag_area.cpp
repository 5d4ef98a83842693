#include "visors/sim/drag_area.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "visors/core/constants.hpp"

namespace visors::sim {

DragArea::DragArea(std::vector<Plate> plates) : plates_(std::move(plates)) {
  for (Plate& p : plates_) p.normal_body.normalize();
}

DragArea DragArea::visors_6u() {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX(), y = Eigen::Vector3d::UnitY(), z = Eigen::Vector3d::UnitZ();
  return DragArea({
      {x, 0.2263 * 0.100},  // body, +-X faces
      {y, 0.366 * 0.100},   // body, +-Y faces
      {z, 0.366 * 0.2263},  // body, +-Z faces
      {x, 0.24},            // solar wing 1
      {x, 0.24},            // solar wing 2
      {y, 0.115},           // side panel
      {z, 0.07},            // zenith-side panel
  });
}

double DragArea::projected_area_m2(const Eigen::Vector3d& v_rel_body_unit) const {
  const double norm = v_rel_body_unit.norm();
  if (!(norm > 0.0)) return 0.0;
  double area_m2 = 0.0;
  for (const Plate& p : plates_) area_m2 += p.area_m2 * std::abs(p.normal_body.dot(v_rel_body_unit));
  return area_m2 / norm;
}

double DragArea::min_projected_area_m2(int samples) const {
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < samples; ++i) best = std::min(best, projected_area_m2(fibonacci_sphere_direction(i, samples)));
  return best;
}

double DragArea::max_projected_area_m2(int samples) const {
  double best = 0.0;
  for (int i = 0; i < samples; ++i) best = std::max(best, projected_area_m2(fibonacci_sphere_direction(i, samples)));
  return best;
}

// z uniform in (-1, 1) by equal-area bands, azimuth advanced by the golden angle pi (3 - sqrt 5)
// (Gonzalez 2010, "Measurement of areas on a sphere using Fibonacci and latitude-longitude lattices").
Eigen::Vector3d fibonacci_sphere_direction(int index, int count) {
  const double golden_angle = core::kPi * (3.0 - std::sqrt(5.0));
  const double z = 1.0 - 2.0 * (index + 0.5) / count;
  const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
  const double phi = golden_angle * index;
  return {rho * std::cos(phi), rho * std::sin(phi), z};
}

Eigen::Vector3d air_velocity_body_unit(const core::StateVector& x_gcrf, const Eigen::Quaterniond& q_body_to_gcrf) {
  const Eigen::Vector3d omega(0.0, 0.0, core::kEarthRotationRate);
  const Eigen::Vector3d v_air = x_gcrf.v - omega.cross(x_gcrf.r);
  return q_body_to_gcrf.conjugate() * v_air.normalized();
}

}  // namespace visors::sim
