#include "visors/mc/campaign_runner.hpp"

#include <algorithm>
#include <map>

#include <fmt/format.h>

#include "visors/sim/navigation_setup.hpp"
#include "visors/sim/truth_dynamics.hpp"

namespace visors::mc {

RunRecord checked_data_files(RunRecord record, const std::vector<sim::DataFileUse>& campaign_files) {
  if (!record.ok || !record.summary.is_object()) return record;
  for (const auto& used : record.summary.value("data_files", nlohmann::json::array())) {
    const std::string key = used.value("key", std::string());
    const auto same_key = std::find_if(campaign_files.begin(), campaign_files.end(),
                                       [&](const sim::DataFileUse& f) { return f.key == key; });
    if (same_key == campaign_files.end()) continue;  // a key the base scenario does not set: nothing to compare
    const std::string checksum = used.value("fnv1a64", std::string());
    if (checksum == same_key->checksum) continue;
    const auto side = [](const std::string& path, const std::string& sum) {
      return path.empty() ? std::string("not found") : fmt::format("{} (FNV-1a 64 {})", path, sum);
    };
    const std::string path = used.contains("path") && used["path"].is_string() ? used["path"].get<std::string>() : "";
    record.ok = false;
    record.error = fmt::format("data file {} differs from the campaign's: {} here, {} for the campaign", key,
                               side(path, checksum), side(same_key->path, same_key->checksum));
    record.summary = nullptr;
    return record;
  }
  return record;
}

namespace {

// A resumed campaign must read the data it began with: the checksums of the files found now are
// those of the store's data_files table (paths may differ: a moved data folder is the same data).
core::Result<bool> same_data_as_stored(ResultsStore& store, const std::vector<sim::DataFileUse>& files) {
  auto info = store.info();
  if (!info.ok()) return info.error();
  std::map<std::string, std::string> found;  // path -> checksum: the table holds each path once
  for (const sim::DataFileUse& f : files) {
    if (!f.path.empty()) found[f.path] = f.checksum;
  }
  std::vector<std::string> now, stored;
  for (const auto& [path, checksum] : found) now.push_back(checksum);
  for (const sim::DataFileUse& f : info->data_files) stored.push_back(f.checksum);
  std::sort(now.begin(), now.end());
  std::sort(stored.begin(), stored.end());
  if (now == stored) return true;
  return core::Error{"data_files", "the data files found now differ from those the campaign began with (results.sqlite, "
                                   "table data_files): resume with the same data, or start another --out"};
}

}  // namespace

void warm_caches(const sim::CampaignScenario& base) {
  (void)sim::make_truth_dynamics(base, base.dsc, "dsc");
  if (base.navigation_mode == sim::NavigationMode::kCdgps) (void)sim::onboard_force_model(base.flight, gnc::Spacecraft::kDsc);
}

core::Result<std::int64_t> run_into_store(const Campaign& campaign, ResultsStore& store, const PoolOptions& options,
                                          const RunnerHooks& hooks, RemoteWorkers* remote) {
  auto base = base_scenario(campaign);
  if (!base.ok()) return base.error();
  const std::vector<sim::DataFileUse> files = sim::data_files_of(*base);
  if (auto ok = store.record_campaign(campaign, sim::campaign_to_toml(*base), files); !ok) return ok.error();
  if (auto same = same_data_as_stored(store, files); !same) return same.error();
  auto stored = store.stored_runs();
  if (!stored.ok()) return stored.error();
  std::vector<std::int64_t> todo;
  for (std::int64_t i = 0; i < campaign.total_runs(); ++i) {
    if (!std::binary_search(stored->begin(), stored->end(), i)) todo.push_back(i);
  }
  const auto sink = [&](const RunSpec& spec, const RunRecord& ran) -> core::Result<bool> {
    const RunRecord record = checked_data_files(ran, files);
    if (auto ok = store.store(spec, record); !ok) return ok;
    if (hooks.stored) hooks.stored(spec, record);
    return true;
  };
  warm_caches(*base);
  if (auto ran = run_local(campaign, todo, options, sink, hooks.progress, remote); !ran.ok()) return ran.error();
  return static_cast<std::int64_t>(todo.size());
}

}  // namespace visors::mc
