#include "visors/mc/campaign_file.hpp"

#include <fmt/format.h>

#include "visors/config/toml_fields.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/text_file.hpp"
#include "visors/mc/run_plan.hpp"

namespace visors::mc {
namespace {

using core::Error;
using namespace config::toml_fields;

std::string quoted_field(const std::string& table, const std::string& key) { return fmt::format("{}.\"{}\"", table, key); }

core::Result<std::vector<ScenarioValue>> value_list(const toml::node* node, const std::string& field) {
  const toml::array* array = node != nullptr ? node->as_array() : nullptr;
  if (array == nullptr || array->empty()) return Error{field, "must be a non-empty array"};
  std::vector<ScenarioValue> out;
  for (std::size_t i = 0; i < array->size(); ++i) {
    VISORS_TRY(value, scenario_value((*array)[i], fmt::format("{}[{}]", field, i)));
    out.push_back(value);
  }
  return out;
}

core::Result<bool> read_set(const toml::table& root, Campaign& c) {
  const toml::table* set = root.get_as<toml::table>("set");
  if (set == nullptr) return true;
  for (const auto& [key, node] : *set) {
    VISORS_TRY(value, scenario_value(node, quoted_field("set", std::string(key.str()))));
    c.set.emplace_back(std::string(key.str()), value);
  }
  return true;
}

core::Result<Dispersion> read_dispersion(const std::string& key, const toml::node& node) {
  const std::string field = quoted_field("dispersions", key);
  const toml::table* spec = node.as_table();
  if (spec == nullptr || spec->size() != 1) {
    return Error{field, "must be one of { normal = { mean, sigma } }, { uniform = { min, max } }, { choice = [...] }"};
  }
  Dispersion d;
  d.key = key;
  const auto entry = spec->begin();
  const std::string kind(entry->first.str());
  const toml::node& body = entry->second;
  const std::string where = field + "." + kind;
  if (kind == "choice") {
    d.kind = Dispersion::Kind::kChoice;
    VISORS_TRY(choices, value_list(&body, where));
    d.choices = choices;
    return d;
  }
  const toml::table* numbers = body.as_table();
  if (numbers == nullptr) return Error{where, "must be a table"};
  if (kind == "normal") {
    if (auto e = check_keys(*numbers, where, {"mean", "sigma"})) return *e;
    d.kind = Dispersion::Kind::kNormal;
    VISORS_TRY(mean, number_at(*numbers, where, "mean", std::nullopt));
    VISORS_TRY(sigma, number_at(*numbers, where, "sigma", std::nullopt));
    if (sigma < 0.0) return Error{where + ".sigma", "must be >= 0"};
    d.a = mean;
    d.b = sigma;
    return d;
  }
  if (kind == "uniform") {
    if (auto e = check_keys(*numbers, where, {"min", "max"})) return *e;
    d.kind = Dispersion::Kind::kUniform;
    VISORS_TRY(lo, number_at(*numbers, where, "min", std::nullopt));
    VISORS_TRY(hi, number_at(*numbers, where, "max", std::nullopt));
    if (hi < lo) return Error{where + ".max", "must be >= min"};
    d.a = lo;
    d.b = hi;
    return d;
  }
  return Error{field, fmt::format("'{}' is not a distribution (normal, uniform, choice)", kind)};
}

core::Result<bool> read_dispersions(const toml::table& root, Campaign& c) {
  const toml::table* table = root.get_as<toml::table>("dispersions");
  if (table == nullptr) return true;
  for (const auto& [key, node] : *table) {
    VISORS_TRY(d, read_dispersion(std::string(key.str()), node));
    c.dispersions.push_back(d);
  }
  return true;
}

core::Result<bool> read_sweeps(const toml::table& root, Campaign& c) {
  const toml::node* node = root.get("sweep");
  if (node == nullptr) return true;
  const toml::array* sweeps = node->as_array();
  if (sweeps == nullptr) return Error{"sweep", "must be an array of tables ([[sweep]])"};
  for (std::size_t i = 0; i < sweeps->size(); ++i) {
    const std::string where = fmt::format("sweep[{}]", i);
    const toml::table* t = (*sweeps)[i].as_table();
    if (t == nullptr) return Error{where, "must be a table with key and values"};
    if (auto e = check_keys(*t, where, {"key", "values"})) return *e;
    VISORS_TRY(key, string_at(*t, where, "key", std::nullopt));
    VISORS_TRY(values, value_list(t->get("values"), where + ".values"));
    c.sweeps.push_back(Sweep{key, values});
  }
  return true;
}

core::Result<bool> read_base_scenario(const toml::table& root, const std::filesystem::path& directory, Campaign& c) {
  VISORS_TRY(path, string_at(root, "", "scenario", std::string("scenarios/campaign.toml")));
  std::optional<std::filesystem::path> found;
  if (const auto beside = directory / path; !std::filesystem::path(path).is_absolute() && std::filesystem::exists(beside)) {
    found = beside;
  } else {
    found = core::files::find_data_file(path);
  }
  if (!found) return Error{"scenario", fmt::format("'{}' not found (beside the campaign, in VISORS_DATA_PATH or data/)", path)};
  auto text = core::files::read_text_file(*found);
  if (!text) return Error{"scenario", fmt::format("'{}' cannot be read", found->string())};
  c.scenario_path = *found;
  c.scenario_text = *text;
  return true;
}

}  // namespace

std::int64_t Campaign::total_runs() const {
  if (sweeps.empty()) return runs;
  std::int64_t values = 0;
  for (const Sweep& s : sweeps) values += static_cast<std::int64_t>(s.values.size());
  return values * runs_per_value;
}

core::Result<Campaign> campaign_from_toml(const std::string& text, const std::filesystem::path& directory,
                                          const std::optional<std::string>& scenario_text) {
  VISORS_TRY(root, parse(text));
  if (auto e = check_keys(root, "", {"name", "scenario", "seed", "runs", "runs_per_value", "time_limit_s", "paired", "set",
                                     "dispersions", "sweep"})) {
    return *e;
  }
  Campaign c;
  c.text = text;
  VISORS_TRY(name, string_at(root, "", "name", std::string("campaign")));
  VISORS_TRY(seed, integer_at(root, "", "seed", 1));
  VISORS_TRY(runs, integer_at(root, "", "runs", 1));
  VISORS_TRY(per_value, integer_at(root, "", "runs_per_value", 1));
  VISORS_TRY(limit, number_at(root, "", "time_limit_s", c.time_limit_s));
  VISORS_TRY(paired, bool_at(root, "", "paired", true));
  if (seed < 0) return Error{"seed", "must be >= 0"};
  if (runs < 1 || runs > 10'000'000) return Error{"runs", "must be in [1, 10000000]"};
  if (per_value < 1 || per_value > 10'000'000) return Error{"runs_per_value", "must be in [1, 10000000]"};
  if (!(limit > 0.0)) return Error{"time_limit_s", "must be > 0"};
  c.name = name;
  c.seed = static_cast<std::uint64_t>(seed);
  c.runs = runs;
  c.runs_per_value = per_value;
  c.time_limit_s = limit;
  c.paired = paired;
  for (auto* reader : {&read_set, &read_dispersions, &read_sweeps}) {
    if (auto ok = reader(root, c); !ok) return ok.error();
  }
  if (!c.sweeps.empty() && root.contains("runs")) return Error{"runs", "with sweeps, give runs_per_value instead"};
  if (scenario_text) {
    VISORS_TRY(path, string_at(root, "", "scenario", std::string("scenarios/campaign.toml")));
    c.scenario_path = path;
    c.scenario_text = *scenario_text;
  } else if (auto ok = read_base_scenario(root, directory, c); !ok) {
    return ok.error();
  }
  if (auto ok = check_against_scenario(c); !ok) return ok.error();
  return c;
}

core::Result<Campaign> load_campaign(const std::string& path) {
  std::optional<std::filesystem::path> found;
  if (std::filesystem::exists(path)) found = path;
  else found = core::files::find_data_file(path);
  if (!found) return Error{"campaign", fmt::format("'{}' not found (nor in VISORS_DATA_PATH or data/)", path)};
  auto text = core::files::read_text_file(*found);
  if (!text) return Error{"campaign", fmt::format("'{}' cannot be read", found->string())};
  return campaign_from_toml(*text, found->parent_path());
}

}  // namespace visors::mc
