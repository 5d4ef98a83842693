#pragma once
// `visors tool NAME`: building blocks with one JSON object in (stdin) and one out (stdout).
// A tool reports bad input by throwing ToolInputError naming the field; the CLI turns it into a
// one-line message on stderr and exit code 2. Angles rad, lengths m, times s.

#include <array>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/status.hpp"

namespace visors::tools {

using Json = nlohmann::json;

class ToolInputError : public std::runtime_error {
 public:
  ToolInputError(std::string field, const std::string& problem)
      : std::runtime_error(field.empty() ? problem : field + ": " + problem),
        field_(std::move(field)) {}
  explicit ToolInputError(const core::Error& error) : ToolInputError(error.field, error.message) {}
  [[nodiscard]] const std::string& field() const { return field_; }

 private:
  std::string field_;
};

/// Unwraps a Result or throws its error as a ToolInputError, with `prefix` prepended to the field.
template <typename T>
T take(core::Result<T> result, const std::string& prefix = "") {
  if (!result.ok()) {
    const auto& e = result.error();
    throw ToolInputError(prefix.empty() ? e.field : (e.field.empty() ? prefix : prefix + "." + e.field),
                         e.message);
  }
  return std::move(result).value();
}

/// The same for a flight check's Status.
inline void take(const core::Status& status, const std::string& prefix = "") {
  if (!status.ok()) (void)take(core::Result<bool>(status.error()), prefix);
}

/// The same for a flight call's Outcome.
template <typename T>
T take(core::Outcome<T> outcome, const std::string& prefix = "") {
  return take(core::Result<T>(std::move(outcome)), prefix);
}

// Field readers: each checks presence, type and finiteness and names `path` in its error.
double require_number(const Json& object, const std::string& key, const std::string& path = "");
std::optional<double> optional_number(const Json& object, const std::string& key,
                                      const std::string& path = "");
std::string require_string(const Json& object, const std::string& key, const std::string& path = "");
Eigen::Vector3d require_vector3(const Json& object, const std::string& key,
                                const std::string& path = "");
/// An array of finite numbers; `size` >= 0 requires exactly that many.
std::vector<double> require_numbers(const Json& object, const std::string& key, const std::string& path = "",
                                    int size = -1);
/// A rows x cols matrix given as an array of rows.
Eigen::MatrixXd require_matrix(const Json& object, const std::string& key, int rows, int cols,
                               const std::string& path = "");
/// a*dROE [m] at `key` (6 numbers) -> dimensionless ROE of a chief with semi-major axis `a`.
astro::RelativeOrbitalElements require_roe_m(const Json& object, const std::string& key, double a);
/// Covariance of a*dROE [m^2] at `key` (6 rows of 6) -> dimensionless; zero when absent.
Eigen::Matrix<double, 6, 6> optional_roe_covariance_m2(const Json& object, const std::string& key, double a);
/// Dimensionless ROE -> a*dROE [m] as a JSON array.
Json roe_to_json_m(const astro::RelativeOrbitalElements& roe, double a);
const Json& require_object(const Json& object, const std::string& key, const std::string& path = "");
/// Rejects any key of `object` not in `allowed` (a typo must not be silently ignored).
void reject_unknown_keys(const Json& object, const std::vector<std::string_view>& allowed,
                         const std::string& path = "");

/// Keplerian elements {a, e, i, raan, argp, M} (m, rad) held by `object` (named `path` in
/// errors); any other key is rejected unless listed in `also_allowed`. Values are not validated
/// here (the astro functions do it and name the field).
astro::KeplerianElements require_keplerian(const Json& object, const std::string& path = "",
                                           const std::vector<std::string_view>& also_allowed = {});

Json to_json(const Eigen::Vector3d& v);

struct ToolEntry {
  std::string_view name;
  std::string_view summary;
  std::function<Json(const Json&)> run;
};

/// Every tool the CLI knows, sorted by name.
const std::vector<ToolEntry>& tool_registry();

/// Called once per tool, from a namespace-scope initialiser in the tool's own file
/// (`const bool registered = register_tool({...});`), so adding a tool touches no other file.
bool register_tool(ToolEntry entry);

}  // namespace visors::tools
