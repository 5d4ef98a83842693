#pragma once
// Tolerant access to summary.json: the report shows whatever the summary holds and "–" for what
// it lacks (an older or partial run), instead of refusing to render.

#include <initializer_list>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace visors::report {

/// The number at `keys` (nested object keys), or NaN when a key is absent or the value is not a
/// number. Booleans are not numbers here.
double summary_number(const nlohmann::json& summary, std::initializer_list<std::string_view> keys);

/// The value at `keys` as display text: a string as is, a number or boolean written out, "" when
/// absent.
std::string summary_text(const nlohmann::json& summary, std::initializer_list<std::string_view> keys);

}  // namespace visors::report
