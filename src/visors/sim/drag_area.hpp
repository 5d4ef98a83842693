#pragma once
// Attitude-dependent drag (projected) area of one spacecraft, modelled as flat plates fixed in
// the body frame: A(v) = sum_i A_i |n_i . v_hat|, v_hat the unit relative wind in body axes.
//
// Approximations (documented, deliberate): a thin plate is one entry and presents A_i |cos| from
// either side, so its two faces are counted once; a closed box body is entered as three plates
// (one per pair of opposite faces), which is exact for a convex box (half the sum over all six
// faces); shadowing of one plate by another is ignored (the area is an upper bound when panels
// hide the body).
//
// Default geometry (visors_6u()): a stand-in sized to reproduce the envelope of 0.15 .. 0.55 m^2
// of Guffanti et al., AAS 23-149, 2023, Table 4 (area by attitude, interpolated from CAD there),
// not the flight CAD:
//   body 6U, 0.366 m (X) x 0.2263 m (Y) x 0.100 m (Z):
//     X faces 0.2263 x 0.100 = 0.02263 m^2, Y faces 0.366 x 0.100 = 0.0366 m^2,
//     Z faces 0.366 x 0.2263 = 0.0828258 m^2;
//   two Sun-facing solar wings, normal +X (lit whenever +X points at the Sun), 0.24 m^2 each;
//   a deployed side panel, normal +Y, 0.115 m^2;
//   a deployed zenith-side panel, normal +Z, 0.07 m^2.
// Per-axis sums a = 0.50263, b = 0.1516, c = 0.1528258 m^2. With all normals on body axes,
// A(v) = a|vx| + b|vy| + c|vz|, so min A = min(a, b, c) = 0.1516 m^2 along Y (since
// |vx| + |vy| + |vz| >= 1) and max A = |(a, b, c)| = 0.54679 m^2 along (a, b, c) (Cauchy-Schwarz).

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "visors/core/state_vector.hpp"

namespace visors::sim {

/// One flat plate: unit normal in the body frame and area [m^2].
struct Plate {
  Eigen::Vector3d normal_body = Eigen::Vector3d::UnitX();
  double area_m2 = 0.0;
};

class DragArea {
 public:
  explicit DragArea(std::vector<Plate> plates);
  /// The default stand-in geometry of the file comment.
  static DragArea visors_6u();

  /// Projected area [m^2] for the relative wind direction in body axes (normalised here; a zero
  /// vector gives 0).
  [[nodiscard]] double projected_area_m2(const Eigen::Vector3d& v_rel_body_unit) const;

  /// Smallest / largest projected area over `samples` directions of a Fibonacci sphere
  /// (deterministic, near-uniform; spacing ~ sqrt(4 pi / samples) rad) [m^2].
  [[nodiscard]] double min_projected_area_m2(int samples = 100000) const;
  [[nodiscard]] double max_projected_area_m2(int samples = 100000) const;

  [[nodiscard]] const std::vector<Plate>& plates() const { return plates_; }

 private:
  std::vector<Plate> plates_;
};

/// Unit velocity relative to the atmosphere co-rotating with the Earth, in the body frame (the
/// direction projected_area_m2 wants).
Eigen::Vector3d air_velocity_body_unit(const core::StateVector& x_gcrf, const Eigen::Quaterniond& q_body_to_gcrf);

/// Direction `index` of `count` on the Fibonacci sphere (golden-angle spiral, equal-area bands).
Eigen::Vector3d fibonacci_sphere_direction(int index, int count);

}  // namespace visors::sim
