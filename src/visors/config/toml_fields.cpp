#include "visors/config/toml_fields.hpp"

#include <cmath>
#include <sstream>

namespace visors::config::toml_fields {

std::string field_name(const std::string& section, std::string_view key) {
  return section.empty() ? std::string(key) : section + "." + std::string(key);
}

Result<toml::table> parse(const std::string& text) {
  try {
    return toml::parse(text);
  } catch (const toml::parse_error& e) {
    std::ostringstream where;
    where << "line " << e.source().begin.line;
    return Error{where.str(), std::string("invalid TOML: ") + std::string(e.description())};
  }
}

std::optional<Error> check_keys(const toml::table& table, const std::string& section,
                                std::initializer_list<std::string_view> allowed) {
  for (const auto& [key, node] : table) {
    bool known = false;
    for (const auto a : allowed) known = known || key.str() == a;
    if (!known) return Error{field_name(section, key.str()), "is not a recognised key"};
  }
  return std::nullopt;
}

Result<double> number_at(const toml::table& table, const std::string& section, std::string_view key,
                         std::optional<double> fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    return Error{field_name(section, key), "is required but missing"};
  }
  const auto value = node->value<double>();
  if (!value) return Error{field_name(section, key), "must be a number"};
  if (!std::isfinite(*value)) return Error{field_name(section, key), "must be finite"};
  return *value;
}

Result<std::int64_t> integer_at(const toml::table& table, const std::string& section,
                                std::string_view key, std::optional<std::int64_t> fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    return Error{field_name(section, key), "is required but missing"};
  }
  if (!node->is_integer()) return Error{field_name(section, key), "must be an integer"};
  return node->as_integer()->get();
}

Result<bool> bool_at(const toml::table& table, const std::string& section, std::string_view key,
                     std::optional<bool> fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    return Error{field_name(section, key), "is required but missing"};
  }
  if (!node->is_boolean()) return Error{field_name(section, key), "must be true or false"};
  return node->as_boolean()->get();
}

Result<std::string> string_at(const toml::table& table, const std::string& section, std::string_view key,
                              std::optional<std::string> fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    return Error{field_name(section, key), "is required but missing"};
  }
  if (!node->is_string()) return Error{field_name(section, key), "must be a string"};
  return node->as_string()->get();
}

Result<Eigen::Vector3d> vector3_at(const toml::table& table, const std::string& section,
                                   std::string_view key, std::optional<Eigen::Vector3d> fallback) {
  const toml::node* node = table.get(key);
  if (node == nullptr) {
    if (fallback) return *fallback;
    return Error{field_name(section, key), "is required but missing"};
  }
  const toml::array* array = node->as_array();
  if (array == nullptr || array->size() != 3) {
    return Error{field_name(section, key), "must be an array of 3 numbers"};
  }
  Eigen::Vector3d v;
  for (int k = 0; k < 3; ++k) {
    const auto value = array->get(static_cast<std::size_t>(k))->value<double>();
    if (!value || !std::isfinite(*value)) {
      return Error{field_name(section, key) + "[" + std::to_string(k) + "]", "must be a finite number"};
    }
    v[k] = *value;
  }
  return v;
}

}  // namespace visors::config::toml_fields
