#pragma once
// One value of a scenario key as a Monte Carlo campaign sets it: a TOML integer, float, boolean,
// string or array of numbers (the scenario's own reader checks that the key takes that type and
// range).

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include <toml++/toml.h>

#include "visors/core/result.hpp"

namespace visors::mc {

using ScenarioValue = std::variant<std::int64_t, double, bool, std::string, std::vector<double>>;

/// The value of a TOML node that is an integer, float, boolean, string or non-empty array of
/// finite numbers (read as floats); an error naming `field` for anything else (tables, dates,
/// nested or mixed arrays).
core::Result<ScenarioValue> scenario_value(const toml::node& node, const std::string& field);

/// As TOML writes it (strings quoted, floats with all their digits): "0.005", "\"ideal\"", "3",
/// "[900.0, 180.0]".
std::string to_text(const ScenarioValue& value);

/// The value as a number when it is one (booleans, strings and arrays: NaN), for plots and
/// statistics.
double to_number(const ScenarioValue& value);

/// Sets `dotted_key` ("propulsion.magnitude_sigma", "forces.gravity.degree") in `root`, creating
/// the tables on the way; an error naming the key when a part of the path is not a table.
core::Result<bool> set_key(toml::table& root, const std::string& dotted_key, const ScenarioValue& value);

}  // namespace visors::mc
