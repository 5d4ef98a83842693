#include "visors/report/summary_fields.hpp"

#include <limits>

namespace visors::report {
namespace {

const nlohmann::json* find(const nlohmann::json& root, std::initializer_list<std::string_view> keys) {
  const nlohmann::json* node = &root;
  for (const std::string_view key : keys) {
    if (!node->is_object()) return nullptr;
    const auto it = node->find(key);
    if (it == node->end()) return nullptr;
    node = &*it;
  }
  return node;
}

}  // namespace

double summary_number(const nlohmann::json& summary, std::initializer_list<std::string_view> keys) {
  const nlohmann::json* node = find(summary, keys);
  if (node == nullptr || !node->is_number()) return std::numeric_limits<double>::quiet_NaN();
  return node->get<double>();
}

std::string summary_text(const nlohmann::json& summary, std::initializer_list<std::string_view> keys) {
  const nlohmann::json* node = find(summary, keys);
  if (node == nullptr || node->is_null()) return {};
  if (node->is_string()) return node->get<std::string>();
  return node->dump();
}

}  // namespace visors::report
