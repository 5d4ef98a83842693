#include "visors/mc/scenario_value.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <fmt/format.h>

namespace visors::mc {

core::Result<ScenarioValue> scenario_value(const toml::node& node, const std::string& field) {
  if (const auto* v = node.as_integer()) return ScenarioValue{v->get()};
  if (const auto* v = node.as_floating_point()) {
    if (!std::isfinite(v->get())) return core::Error{field, "must be finite"};
    return ScenarioValue{v->get()};
  }
  if (const auto* v = node.as_boolean()) return ScenarioValue{v->get()};
  if (const auto* v = node.as_string()) return ScenarioValue{v->get()};
  if (const auto* array = node.as_array(); array != nullptr && !array->empty()) {
    std::vector<double> numbers;
    for (std::size_t k = 0; k < array->size(); ++k) {
      const toml::node& element = (*array)[k];
      const std::optional<double> number = element.is_number() ? element.value<double>() : std::nullopt;
      if (!number || !std::isfinite(*number)) return core::Error{fmt::format("{}[{}]", field, k), "must be a finite number"};
      numbers.push_back(*number);
    }
    return ScenarioValue{std::move(numbers)};
  }
  return core::Error{field, "must be a number, a boolean, a string or a non-empty array of numbers"};
}

namespace {

std::string float_text(double v) {
  std::string s = fmt::format("{}", v);  // the shortest text that reads back to v
  if (s.find_first_of(".en") == std::string::npos) s += ".0";  // stays a TOML float
  return s;
}

}  // namespace

std::string to_text(const ScenarioValue& value) {
  struct Text {
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const { return float_text(v); }
    std::string operator()(const std::vector<double>& v) const {
      std::string out = "[";
      for (std::size_t k = 0; k < v.size(); ++k) out += (k > 0 ? ", " : "") + float_text(v[k]);
      return out + "]";
    }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const {
      std::string out = "\"";
      for (const char c : v) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
      }
      return out + "\"";
    }
  };
  return std::visit(Text{}, value);
}

double to_number(const ScenarioValue& value) {
  if (const auto* i = std::get_if<std::int64_t>(&value)) return static_cast<double>(*i);
  if (const auto* d = std::get_if<double>(&value)) return *d;
  return std::numeric_limits<double>::quiet_NaN();
}

core::Result<bool> set_key(toml::table& root, const std::string& dotted_key, const ScenarioValue& value) {
  toml::table* table = &root;
  std::size_t start = 0;
  for (std::size_t dot = dotted_key.find('.'); dot != std::string::npos; dot = dotted_key.find('.', start)) {
    const std::string part = dotted_key.substr(start, dot - start);
    if (part.empty()) return core::Error{dotted_key, "is not a key path (an empty part)"};
    toml::node* next = table->get(part);
    if (next == nullptr) next = &table->insert_or_assign(part, toml::table{}).first->second;
    table = next->as_table();
    if (table == nullptr) return core::Error{dotted_key, fmt::format("'{}' is a value, not a table", part)};
    start = dot + 1;
  }
  const std::string leaf = dotted_key.substr(start);
  if (leaf.empty()) return core::Error{dotted_key, "is not a key path (an empty part)"};
  if (const auto* numbers = std::get_if<std::vector<double>>(&value)) {
    toml::array array;
    for (const double v : *numbers) array.push_back(v);
    table->insert_or_assign(leaf, std::move(array));
    return true;
  }
  std::visit(
      [&](const auto& v) {
        if constexpr (!std::is_same_v<std::decay_t<decltype(v)>, std::vector<double>>) table->insert_or_assign(leaf, v);
      },
      value);
  return true;
}

}  // namespace visors::mc
