#include "visors/dynamics/files/force_model_files.hpp"

#include <optional>
#include <string>
#include <utility>

#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/dynamics/files/icgem_file.hpp"
#include "visors/dynamics/files/nrlmsise00_file.hpp"
#include "visors/dynamics/files/space_weather_file.hpp"
#include "visors/dynamics/gravity_field.hpp"

namespace visors::dynamics::files {
namespace {

using core::Error;

Error nested(const std::string& section, const Error& e) {
  return {e.field.empty() ? section : section + "." + e.field, e.message};
}

// gravity.model, or the embedded field (with `fallback` set) when allowed.
core::Result<GravityField> gravity_field_for(const GravityConfig& config, std::optional<std::string>& fallback) {
  auto field = load_gravity_field(config.model, config.degree);
  if (field) return field;
  if (!config.allow_embedded_fallback) return nested("gravity.model", field.error());
  GravityField embedded = embedded_gravity_field();
  fallback = "gravity.model: " + field.error().describe() + "; using the embedded degree-" +
             std::to_string(embedded.max_degree) + " field";
  return embedded;
}

// The space-weather, NRLMSISE-00 and EOP tables into `data`, or the first table file found but
// unreadable.
std::optional<Error> load_tables(const ForceModelConfig& config, ForceModelData& data) {
  if (config.drag.enabled && config.drag.atmosphere == AtmosphereKind::kNrlmsise00) {
    const auto path = core::files::find_data_file(config.drag.nrlmsise00_coefficients);
    if (path) {
      auto tables = read_nrlmsise00_coefficients(*path);
      if (!tables) return nested("drag.nrlmsise00_coefficients", tables.error());
      data.nrlmsise00.emplace(std::move(tables).value());
    } else {
      data.atmosphere_fallback = "drag.nrlmsise00_coefficients: '" + config.drag.nrlmsise00_coefficients +
                                 "' not found; Harris-Priester maximum densities instead of NRLMSISE-00";
    }
  }
  if (config.drag.enabled && !config.drag.space_weather.empty()) {
    const auto path = core::files::find_data_file(config.drag.space_weather);
    if (path) {
      auto table = read_space_weather_file(*path);
      if (!table) return nested("drag.space_weather", table.error());
      data.space_weather.emplace(std::move(table).value());
    } else {
      data.space_weather_fallback = "drag.space_weather: '" + config.drag.space_weather +
                                    "' not found; constant f107/f107a/ap of the configuration";
    }
  }
  if (!config.earth_frame.eop.empty()) {
    const auto path = core::files::find_data_file(config.earth_frame.eop);
    if (path) {
      auto table = core::files::read_eop_file(*path);
      if (!table) return nested("earth_frame.eop", table.error());
      data.eop.emplace(std::move(table).value());
    } else {
      data.eop_fallback = "earth_frame.eop: '" + config.earth_frame.eop + "' not found; zero polar motion and UT1-UTC";
    }
  }
  return std::nullopt;
}

}  // namespace

core::Result<ForceModel> load_force_model(const ForceModelConfig& config, const SpacecraftProperties& spacecraft) {
  if (const core::Status ok = ForceModel::check_inputs(config, spacecraft); !ok) return ok.error();
  ForceModelData data;
  auto field = gravity_field_for(config.gravity, data.gravity_fallback);
  if (!field) return field.error();
  data.gravity_field = std::move(field).value();
  // An unreadable table file is reported after create()'s checks of the gravity truncation and
  // the drag settings, which come first in the order of the configuration.
  const std::optional<Error> table_error = load_tables(config, data);
  auto model = ForceModel::create(config, spacecraft, std::move(data));
  if (model && table_error) return *table_error;
  return model;
}

}  // namespace visors::dynamics::files
