#pragma once
// Typed, validated reads from a parsed TOML table for configuration files (scenarios, force
// models). Ground-side helper: flight code receives configuration as plain structs. Every error
// names the full dotted field ("forces.gravity.degree") and the problem; unknown keys are errors
// so that a typo is never silently ignored.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <toml++/toml.h>

#include "visors/core/result.hpp"

namespace visors::config::toml_fields {

using core::Error;
using core::Result;

/// "section.key" (or "key" when section is empty).
std::string field_name(const std::string& section, std::string_view key);

/// Parses TOML text; a syntax error names its line.
Result<toml::table> parse(const std::string& text);

/// An error for the first key of `table` not in `allowed`; nullopt when all are known.
std::optional<Error> check_keys(const toml::table& table, const std::string& section,
                                std::initializer_list<std::string_view> allowed);

/// A finite number (integers accepted); `fallback` when absent, an error when absent without one.
Result<double> number_at(const toml::table& table, const std::string& section, std::string_view key,
                         std::optional<double> fallback);
Result<std::int64_t> integer_at(const toml::table& table, const std::string& section,
                                std::string_view key, std::optional<std::int64_t> fallback);
Result<bool> bool_at(const toml::table& table, const std::string& section, std::string_view key,
                     std::optional<bool> fallback);
Result<std::string> string_at(const toml::table& table, const std::string& section, std::string_view key,
                              std::optional<std::string> fallback);
/// An array of 3 finite numbers.
Result<Eigen::Vector3d> vector3_at(const toml::table& table, const std::string& section,
                                   std::string_view key, std::optional<Eigen::Vector3d> fallback);

}  // namespace visors::config::toml_fields

/// Unwraps a Result into `const auto var`, or returns its error from the enclosing function.
#define VISORS_TRY(var, expr)                            \
  auto var##_result = (expr);                            \
  if (!var##_result.ok()) return var##_result.error();   \
  const auto var = std::move(var##_result).value()
