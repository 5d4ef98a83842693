#pragma once
// A campaign into its results store: the campaign recorded (or checked to be the stored one),
// then every run the store does not hold yet run on the local pool and stored as it ends. A fresh
// store and a resumed one go the same way; the stored content depends only on the campaign.

#include <functional>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/mc/campaign_file.hpp"
#include "visors/mc/local_pool.hpp"
#include "visors/mc/results_store.hpp"
#include "visors/sim/data_provenance.hpp"

namespace visors::mc {

struct RunnerHooks {
  std::function<void(const PoolProgress&)> progress;
  std::function<void(const RunSpec&, const RunRecord&)> stored;  // after each run is stored
};

/// The number of runs still to do when it started (0 when the store was complete).
/// `remote` (optional): other ranks sharing the runs (mc/mpi_campaign.hpp).
core::Result<std::int64_t> run_into_store(const Campaign& campaign, ResultsStore& store, const PoolOptions& options,
                                          const RunnerHooks& hooks = {}, RemoteWorkers* remote = nullptr);

/// The run as it should be stored: failed, with the reason, when a data file it read differs
/// from the campaign's (`campaign_files`, what the coordinating process found): another file of
/// that name, a different checksum, or found on one side only. An MPI rank on a node with other
/// data would otherwise mix results computed from different inputs into one campaign.
RunRecord checked_data_files(RunRecord record, const std::vector<sim::DataFileUse>& campaign_files);

/// Parses the base scenario's gravity fields in this process (dynamics/files/icgem_file.hpp keeps
/// them), so that the runs forked from it find them parsed: half a run's set-up time.
void warm_caches(const sim::CampaignScenario& base);

}  // namespace visors::mc
