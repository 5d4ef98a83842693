#include "apps/tools/tool.hpp"

#include <algorithm>
#include <cmath>

namespace visors::tools {
namespace {

std::string join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

const Json& require_member(const Json& object, const std::string& key, const std::string& path) {
  if (!object.is_object()) throw ToolInputError(path, "must be a JSON object");
  const auto it = object.find(key);
  if (it == object.end()) throw ToolInputError(join(path, key), "is required but missing");
  return *it;
}

double finite_number(const Json& value, const std::string& field) {
  if (!value.is_number()) throw ToolInputError(field, "must be a number");
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw ToolInputError(field, "must be finite");
  return x;
}

}  // namespace

double require_number(const Json& object, const std::string& key, const std::string& path) {
  return finite_number(require_member(object, key, path), join(path, key));
}

std::optional<double> optional_number(const Json& object, const std::string& key,
                                      const std::string& path) {
  if (!object.is_object() || !object.contains(key)) return std::nullopt;
  return finite_number(object.at(key), join(path, key));
}

std::string require_string(const Json& object, const std::string& key, const std::string& path) {
  const Json& value = require_member(object, key, path);
  if (!value.is_string()) throw ToolInputError(join(path, key), "must be a string");
  return value.get<std::string>();
}

Eigen::Vector3d require_vector3(const Json& object, const std::string& key,
                                const std::string& path) {
  const std::string field = join(path, key);
  const Json& value = require_member(object, key, path);
  if (!value.is_array() || value.size() != 3) {
    throw ToolInputError(field, "must be an array of 3 numbers");
  }
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) {
    v[k] = finite_number(value[static_cast<std::size_t>(k)], field + "[" + std::to_string(k) + "]");
  }
  return v;
}

std::vector<double> require_numbers(const Json& object, const std::string& key, const std::string& path, int size) {
  const std::string field = join(path, key);
  const Json& value = require_member(object, key, path);
  if (!value.is_array() || (size >= 0 && value.size() != static_cast<std::size_t>(size))) {
    throw ToolInputError(field, size >= 0 ? "must be an array of " + std::to_string(size) + " numbers"
                                          : "must be an array of numbers");
  }
  std::vector<double> out;
  out.reserve(value.size());
  for (std::size_t k = 0; k < value.size(); ++k) out.push_back(finite_number(value[k], field + "[" + std::to_string(k) + "]"));
  return out;
}

Eigen::MatrixXd require_matrix(const Json& object, const std::string& key, int rows, int cols, const std::string& path) {
  const std::string field = join(path, key);
  const Json& value = require_member(object, key, path);
  const std::string shape = "must be " + std::to_string(rows) + " rows of " + std::to_string(cols) + " numbers";
  if (!value.is_array() || value.size() != static_cast<std::size_t>(rows)) throw ToolInputError(field, shape);
  Eigen::MatrixXd m(rows, cols);
  for (int r = 0; r < rows; ++r) {
    const Json& row = value[static_cast<std::size_t>(r)];
    if (!row.is_array() || row.size() != static_cast<std::size_t>(cols)) throw ToolInputError(field, shape);
    for (int c = 0; c < cols; ++c) {
      m(r, c) = finite_number(row[static_cast<std::size_t>(c)],
                              field + "[" + std::to_string(r) + "][" + std::to_string(c) + "]");
    }
  }
  return m;
}

astro::RelativeOrbitalElements require_roe_m(const Json& object, const std::string& key, double a) {
  const std::vector<double> v = require_numbers(object, key, "", 6);
  astro::RelativeOrbitalElements roe;
  for (int k = 0; k < 6; ++k) roe[k] = v[static_cast<std::size_t>(k)] / a;
  return roe;
}

Eigen::Matrix<double, 6, 6> optional_roe_covariance_m2(const Json& object, const std::string& key, double a) {
  if (!object.contains(key)) return Eigen::Matrix<double, 6, 6>::Zero();
  return require_matrix(object, key, 6, 6) / (a * a);
}

Json roe_to_json_m(const astro::RelativeOrbitalElements& roe, double a) {
  Json out = Json::array();
  for (int k = 0; k < 6; ++k) out.push_back(a * roe[k]);
  return out;
}

const Json& require_object(const Json& object, const std::string& key, const std::string& path) {
  const Json& value = require_member(object, key, path);
  if (!value.is_object()) throw ToolInputError(join(path, key), "must be a JSON object");
  return value;
}

void reject_unknown_keys(const Json& object, const std::vector<std::string_view>& allowed,
                         const std::string& path) {
  for (const auto& [key, value] : object.items()) {
    bool known = false;
    for (const auto& a : allowed) known = known || (a == key);
    if (!known) throw ToolInputError(join(path, key), "is not a recognised field");
  }
}

astro::KeplerianElements require_keplerian(const Json& object, const std::string& path,
                                           const std::vector<std::string_view>& also_allowed) {
  std::vector<std::string_view> allowed = {"a", "e", "i", "raan", "argp", "M"};
  allowed.insert(allowed.end(), also_allowed.begin(), also_allowed.end());
  reject_unknown_keys(object, allowed, path);
  return {require_number(object, "a", path),    require_number(object, "e", path),
          require_number(object, "i", path),    require_number(object, "raan", path),
          require_number(object, "argp", path), require_number(object, "M", path)};
}

Json to_json(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }

namespace {
std::vector<ToolEntry>& mutable_registry() {
  static std::vector<ToolEntry> registry;
  return registry;
}
}  // namespace

bool register_tool(ToolEntry entry) {
  auto& registry = mutable_registry();
  const auto at = std::lower_bound(registry.begin(), registry.end(), entry.name,
                                   [](const ToolEntry& e, std::string_view n) { return e.name < n; });
  registry.insert(at, std::move(entry));
  return true;
}

const std::vector<ToolEntry>& tool_registry() { return mutable_registry(); }

}  // namespace visors::tools
