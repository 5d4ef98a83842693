#include "mc/scenario_value.hpp"

#include <cmath>
#include <limits>

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
  return core::Error{field, "must be a number, a boolean or a string"};
}

std::string to_text(const ScenarioValue& value) {
  struct Text {
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(double v) const {
      std::string s = fmt::format("{}", v);  // the shortest text that reads back to v
      if (s.find_first_of(".en") == std::string::npos) s += ".0";  // stays a TOML float
      return s;
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
  std::visit([&](const auto& v) { table->insert_or_assign(leaf, v); }, value);
  return true;
}

}  // namespace visors::mc
