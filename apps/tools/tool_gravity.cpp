// `visors tool gravity`: spherical-harmonic gravity of an ICGEM model at a body-fixed position.
//   {"model": "gravity/GGM05S_d90.gfc" (data-relative or a path), "degree": n, "order"?: m
//    (default n), "r_itrf": [x, y, z] m}
//     -> {"a_itrf": [3] m/s^2, "potential": m^2/s^2, "gm": m^3/s^2, "radius": m, "model_name",
//         "degree", "order"}
// Normalised Cunningham V/W recursion (dynamics/spherical_harmonic_gravity.hpp); the model's own
// GM and R are used. No embedded fallback here: a missing file is an input error.

#include <cmath>
#include <string>

#include "visors/core/constants.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"
#include "apps/tools/tool.hpp"

namespace visors::tools {
namespace {

int require_integer(const Json& in, const std::string& key) {
  const double x = require_number(in, key);
  if (x != std::floor(x) || std::abs(x) > 1e6) throw ToolInputError(key, "must be an integer");
  return static_cast<int>(x);
}

Json run_gravity(const Json& in) {
  reject_unknown_keys(in, {"model", "degree", "order", "r_itrf"});
  const std::string model = require_string(in, "model");
  const int degree = require_integer(in, "degree");
  const int order = in.contains("order") ? require_integer(in, "order") : degree;
  const Eigen::Vector3d r_itrf = require_vector3(in, "r_itrf");
  if (degree < 0) throw ToolInputError("degree", "must be >= 0");

  // The whole file is read so that a degree above the file's is reported against "degree" by
  // SphericalHarmonicGravity::create (the file is at most a few MB).
  const core::Result<dynamics::GravityField> field = dynamics::files::load_gravity_field(model, -1);
  if (!field.ok()) throw ToolInputError("model", field.error().describe());
  dynamics::SphericalHarmonicGravity gravity =
      take(dynamics::SphericalHarmonicGravity::create(field.value(), degree, order));

  // Below the polar radius R(1 - f) (WGS-84 flattening) the point is certainly inside the Earth,
  // where the series is meaningless (and r = 0 is outside the evaluation's domain).
  const double polar_radius = field->radius * (1.0 - core::kWgs84Flattening);
  if (!(r_itrf.norm() >= polar_radius)) {
    throw ToolInputError("r_itrf", "position is inside the Earth (|r| = " + std::to_string(r_itrf.norm()) +
                                       " m is below the polar radius " + std::to_string(polar_radius) + " m)");
  }
  const dynamics::GravityAccelerationPotential out = gravity.acceleration_and_potential(r_itrf);
  return Json{{"a_itrf", to_json(out.a_itrf)},
              {"potential", out.potential},
              {"gm", field->gm},
              {"radius", field->radius},
              {"model_name", field->model_name},
              {"degree", degree},
              {"order", order}};
}

const bool registered = register_tool(
    {"gravity", "spherical-harmonic gravity {model (.gfc), degree, order?, r_itrf m} -> a_itrf, potential",
     run_gravity});

}  // namespace
}  // namespace visors::tools
