#include "visors/mc/run_plan.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include <fmt/format.h>

#include "visors/config/toml_fields.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::mc {
namespace {

using core::Error;
using Parameters = std::vector<std::pair<std::string, ScenarioValue>>;

ScenarioValue draw(const Dispersion& d, std::uint64_t run_seed) {
  sim::RandomStream rng(run_seed, "mc." + d.key);
  switch (d.kind) {
    case Dispersion::Kind::kNormal: return d.a + d.b * rng.normal();
    case Dispersion::Kind::kUniform: return d.a + (d.b - d.a) * rng.uniform();
    case Dispersion::Kind::kChoice: {
      const auto n = d.choices.size();
      const auto k = std::min(n - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(n)));
      return d.choices[k];
    }
  }
  return 0.0;
}

// The base scenario's table with `set`, then `parameters`, and `seed` (when given) applied, read
// by the scenario's reader. `origin` names where the parameters were written, for the errors.
core::Result<sim::CampaignScenario> apply(const Campaign& c, const Parameters& parameters, std::optional<std::uint64_t> seed,
                                          const std::string& origin) {
  auto parsed = config::toml_fields::parse(c.scenario_text);
  if (!parsed.ok()) return Error{"scenario", fmt::format("{}: {}", parsed.error().field, parsed.error().message)};
  toml::table root = std::move(parsed).value();
  const auto put = [&](const std::string& key, const ScenarioValue& value, const std::string& where) -> core::Result<bool> {
    if (key == "seed") return Error{where, "the seed is the campaign's (seed, paired), not a key to set"};
    if (auto ok = set_key(root, key, value); !ok) return Error{where, ok.error().message};
    return true;
  };
  for (const auto& [key, value] : c.set) {
    if (auto ok = put(key, value, fmt::format("set.\"{}\"", key)); !ok) return ok.error();
  }
  for (const auto& [key, value] : parameters) {
    if (auto ok = put(key, value, origin); !ok) return ok.error();
  }
  if (seed) root.insert_or_assign("seed", static_cast<std::int64_t>(*seed));
  std::ostringstream text;
  text << root;
  auto scenario = sim::campaign_from_toml(text.str());
  if (!scenario.ok()) {
    return Error{origin, fmt::format("{}: {}", scenario.error().field, scenario.error().message)};
  }
  return scenario;
}

}  // namespace

std::uint64_t splitmix64(std::uint64_t x) {
  std::uint64_t z = x + 0x9E3779B97F4A7C15ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

RunSpec run_spec(const Campaign& c, std::int64_t index) {
  RunSpec run;
  run.index = index;
  run.replicate = index;
  std::int64_t first = 0;
  for (std::size_t s = 0; s < c.sweeps.size(); ++s) {
    const auto count = static_cast<std::int64_t>(c.sweeps[s].values.size()) * c.runs_per_value;
    if (index < first + count) {
      run.sweep = static_cast<int>(s);
      run.value = static_cast<int>((index - first) / c.runs_per_value);
      run.replicate = (index - first) % c.runs_per_value;
      run.parameters.emplace_back(c.sweeps[s].key, c.sweeps[s].values[static_cast<std::size_t>(run.value)]);
      break;
    }
    first += count;
  }
  const std::uint64_t stream = c.paired ? static_cast<std::uint64_t>(run.replicate) : static_cast<std::uint64_t>(index);
  run.seed = splitmix64(c.seed ^ splitmix64(stream)) & 0x7FFF'FFFF'FFFF'FFFFULL;
  for (const Dispersion& d : c.dispersions) run.parameters.emplace_back(d.key, draw(d, run.seed));
  return run;
}

core::Result<sim::CampaignScenario> scenario_for(const Campaign& c, const RunSpec& run) {
  return apply(c, run.parameters, run.seed, fmt::format("run {}", run.index));
}

core::Result<sim::CampaignScenario> base_scenario(const Campaign& c) { return apply(c, {}, std::nullopt, "set"); }

core::Result<bool> check_against_scenario(const Campaign& c) {
  if (auto base = base_scenario(c); !base.ok()) return base.error();
  const auto check = [&](const std::string& key, const ScenarioValue& value, const std::string& where) -> core::Result<bool> {
    if (auto s = apply(c, {{key, value}}, std::nullopt, where); !s.ok()) return s.error();
    return true;
  };
  for (std::size_t i = 0; i < c.sweeps.size(); ++i) {
    for (const ScenarioValue& v : c.sweeps[i].values) {
      if (auto ok = check(c.sweeps[i].key, v, fmt::format("sweep[{}].values", i)); !ok) return ok;
    }
  }
  for (const Dispersion& d : c.dispersions) {
    const std::string where = fmt::format("dispersions.\"{}\"", d.key);
    std::vector<ScenarioValue> extremes = d.choices;
    if (d.kind == Dispersion::Kind::kNormal) extremes = {d.a - 3.0 * d.b, d.a + 3.0 * d.b};
    if (d.kind == Dispersion::Kind::kUniform) extremes = {d.a, d.b};
    for (const ScenarioValue& v : extremes) {
      if (auto ok = check(d.key, v, where); !ok) return ok;
    }
  }
  return true;
}

}  // namespace visors::mc
