#pragma once
// The ground side of the force model: the files a ForceModelConfig names (gravity field,
// NRLMSISE-00 coefficients, space weather, EOP) found through the data search path (core/files/data_path.hpp), read, and given to
// ForceModel::create. Ground side (visors_dynamics_files).

#include "visors/core/result.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/force_model_config.hpp"

namespace visors::dynamics::files {

/// The force model of `config` for `spacecraft` with its files read:
///   - gravity.model, read to gravity.degree; when it cannot be read and
///     gravity.allow_embedded_fallback, the embedded field with a warning, else an error
///     ("gravity.model...");
///   - drag.nrlmsise00_coefficients (drag enabled with the NRLMSISE-00 atmosphere); not found:
///     the Harris-Priester maximum densities with a warning; found but unreadable: an error
///     ("drag.nrlmsise00_coefficients...");
///   - drag.space_weather (drag enabled, name not empty); not found: the constant drag.activity
///     with a warning; found but unreadable: an error ("drag.space_weather...");
///   - earth_frame.eop (name not empty); not found: zero EOP with a warning; found but
///     unreadable: an error ("earth_frame.eop...").
/// With several problems, the error is the first of: spacecraft and empirical acceleration,
/// gravity file, gravity degree and order, drag settings, NRLMSISE-00 file, space-weather file,
/// EOP file.
core::Result<ForceModel> load_force_model(const ForceModelConfig& config, const SpacecraftProperties& spacecraft);

}  // namespace visors::dynamics::files
