#include "visors/sim/spacecraft_geometry.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace visors::sim {
namespace {

bool valid_sigma(double sigma) { return std::isfinite(sigma) && sigma >= 0.0; }

Eigen::Vector3d normal_vector(RandomStream& rng, double sigma) {
  const double x = rng.normal(sigma), y = rng.normal(sigma), z = rng.normal(sigma);  // fixed order
  return {x, y, z};
}

// Axis tilted by the rotation vector t1 e1 + t2 e2 (file comment of the header).
Eigen::Vector3d tilted_axis(const Eigen::Vector3d& axis, double t1, double t2) {
  Eigen::Index least = 0;
  axis.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d e1 = axis.cross(Eigen::Vector3d::Unit(least)).normalized();
  const Eigen::Vector3d e2 = axis.cross(e1);
  const Eigen::Vector3d rotation = t1 * e1 + t2 * e2;
  const double angle = rotation.norm();
  if (angle == 0.0) return axis;  // exact nominal for zero sigma
  return (Eigen::AngleAxisd(angle, rotation / angle) * axis).normalized();
}

}  // namespace

core::Result<bool> GeometrySettings::validate() const {
  if (!com_nominal_body_m.allFinite()) return core::Error{"com_nominal_body_m", "must be finite"};
  if (!valid_sigma(com_sigma_m)) return core::Error{"com_sigma_m", "must be finite and >= 0 m"};
  if (!valid_sigma(com_knowledge_error_m)) return core::Error{"com_knowledge_error_m", "must be finite and >= 0 m"};
  if (!payload_nominal_body_m.allFinite()) return core::Error{"payload_nominal_body_m", "must be finite"};
  if (!valid_sigma(payload_position_sigma_m)) {
    return core::Error{"payload_position_sigma_m", "must be finite and >= 0 m"};
  }
  if (!payload_axis_nominal_body.allFinite() || !(payload_axis_nominal_body.norm() > 0.0)) {
    return core::Error{"payload_axis_nominal_body", "must be a finite non-zero vector"};
  }
  if (!valid_sigma(payload_pointing_sigma_rad)) {
    return core::Error{"payload_pointing_sigma_rad", "must be finite and >= 0 rad"};
  }
  if (!valid_sigma(phase_center_knowledge_sigma_m)) {
    return core::Error{"phase_center_knowledge_sigma_m", "must be finite and >= 0 m"};
  }
  return true;
}

SpacecraftGeometry SpacecraftGeometry::draw(const GeometrySettings& settings, RandomStream& rng) {
  SpacecraftGeometry g;
  g.com_nominal_body_m_ = settings.com_nominal_body_m;
  g.payload_nominal_body_m_ = settings.payload_nominal_body_m;
  g.payload_axis_nominal_body_ = settings.payload_axis_nominal_body.normalized();
  g.com_body_m_ = g.com_nominal_body_m_ + normal_vector(rng, settings.com_sigma_m);
  g.payload_body_m_ = g.payload_nominal_body_m_ + normal_vector(rng, settings.payload_position_sigma_m);
  const double t1 = rng.normal(settings.payload_pointing_sigma_rad);
  const double t2 = rng.normal(settings.payload_pointing_sigma_rad);
  g.payload_axis_body_ = tilted_axis(g.payload_axis_nominal_body_, t1, t2);
  const Eigen::Vector3d direction = normal_vector(rng, 1.0);  // isotropic: a normal vector's direction
  const double norm = direction.norm();
  if (norm > 0.0) g.com_body_m_ += settings.com_knowledge_error_m / norm * direction;
  g.phase_center_error_body_m_ = normal_vector(rng, settings.phase_center_knowledge_sigma_m);
  return g;
}

}  // namespace visors::sim
