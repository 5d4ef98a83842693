#include "mc/campaign_runner.hpp"

#include <algorithm>

#include "sim/navigation_setup.hpp"
#include "sim/truth_dynamics.hpp"

namespace visors::mc {

void warm_caches(const sim::CampaignScenario& base) {
  (void)sim::make_truth_dynamics(base, base.dsc, "dsc");
  if (base.navigation_mode == sim::NavigationMode::kCdgps) (void)sim::onboard_force_model(base.dsc, "dsc");
}

core::Result<std::int64_t> run_into_store(const Campaign& campaign, ResultsStore& store, const PoolOptions& options,
                                          const RunnerHooks& hooks, RemoteWorkers* remote) {
  auto base = base_scenario(campaign);
  if (!base.ok()) return base.error();
  if (auto ok = store.record_campaign(campaign, sim::campaign_to_toml(*base), sim::data_files_of(*base)); !ok) return ok.error();
  auto stored = store.stored_runs();
  if (!stored.ok()) return stored.error();
  std::vector<std::int64_t> todo;
  for (std::int64_t i = 0; i < campaign.total_runs(); ++i) {
    if (!std::binary_search(stored->begin(), stored->end(), i)) todo.push_back(i);
  }
  const auto sink = [&](const RunSpec& spec, const RunRecord& record) -> core::Result<bool> {
    if (auto ok = store.store(spec, record); !ok) return ok;
    if (hooks.stored) hooks.stored(spec, record);
    return true;
  };
  warm_caches(*base);
  if (auto ran = run_local(campaign, todo, options, sink, hooks.progress, remote); !ran.ok()) return ran.error();
  return static_cast<std::int64_t>(todo.size());
}

}  // namespace visors::mc
