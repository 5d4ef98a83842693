#include "visors/dynamics/solar_radiation_pressure.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace visors::dynamics {

double cylindrical_shadow(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double earth_radius) {
  const Eigen::Vector3d e_sun = r_sun.normalized();
  const double along = r.dot(e_sun);  // < 0: on the night side of the terminator plane
  if (along >= 0.0) return 1.0;
  const Eigen::Vector3d across = r - along * e_sun;
  return across.squaredNorm() < earth_radius * earth_radius ? 0.0 : 1.0;
}

double conical_shadow(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double earth_radius) {
  const Eigen::Vector3d to_sun = r_sun - r;
  const double d_sun = to_sun.norm();
  const double d_earth = r.norm();
  const double a = std::asin(std::min(1.0, kSunRadius / d_sun));       // apparent solar radius
  const double b = std::asin(std::min(1.0, earth_radius / d_earth));   // apparent Earth radius
  const double c = std::acos(std::clamp(-r.dot(to_sun) / (d_earth * d_sun), -1.0, 1.0));  // separation
  if (c >= a + b) return 1.0;       // disks apart: full Sun
  if (c <= b - a) return 0.0;       // Sun disk behind the Earth disk: umbra
  if (c <= a - b) return 1.0 - (b * b) / (a * a);  // Earth disk inside the Sun disk (annular)
  // Partial overlap of two circles of radii a, b at distance c (M&G eq. 3.87).
  const double x = (c * c + a * a - b * b) / (2.0 * c);
  const double y = std::sqrt(std::max(0.0, a * a - x * x));
  const double overlap = a * a * std::acos(std::clamp(x / a, -1.0, 1.0)) +
                         b * b * std::acos(std::clamp((c - x) / b, -1.0, 1.0)) - c * y;
  return std::clamp(1.0 - overlap / (std::numbers::pi * a * a), 0.0, 1.0);
}

Eigen::Vector3d srp_acceleration(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double nu,
                                 double p_1au, double cr, double area_m2, double mass_kg) {
  const Eigen::Vector3d d = r - r_sun;  // Sun -> satellite
  const double d2 = d.squaredNorm();
  const double scale =
      nu * p_1au * cr * (area_m2 / mass_kg) * kAstronomicalUnit * kAstronomicalUnit / (d2 * std::sqrt(d2));
  return scale * d;
}

}  // namespace visors::dynamics
