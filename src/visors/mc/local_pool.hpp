#pragma once
// The runs of a campaign on this host: up to `workers` at a time, each in its own child process
// (fork), which sends its RunRecord back through a pipe and exits. A process per run is the
// isolation a long campaign needs: a run that crashes (a signal) or outlives its time limit
// (killed) is recorded as failed with the reason, and the campaign goes on; the simulation itself
// needs no thread safety. The parent is single-threaded: it starts children, reads their pipes
// (poll), reaps them and hands each record to `on_finished` in the order they end. A child dies
// with its parent (PR_SET_PDEATHSIG), so killing the campaign leaves no orphan runs.
//
// Cost per run over the simulation: one fork of the parent (~1 ms) plus the scenario's set-up,
// which every run pays anyway (its data files are read again: ~20 ms, `visors mc` prints it).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <vector>

#include "visors/core/result.hpp"
#include "visors/mc/campaign_file.hpp"
#include "visors/mc/run_plan.hpp"
#include "visors/mc/run_record.hpp"

namespace visors::mc {

struct PoolOptions {
  int workers = 1;
  std::filesystem::path scratch;  // run directories (removed after each run unless keep_runs)
  bool keep_runs = false;
};

struct PoolProgress {
  std::int64_t finished = 0, failed = 0, running = 0, total = 0;
  double wall_s = 0.0;
};

using RunSink = std::function<core::Result<bool>(const RunSpec&, const RunRecord&)>;

/// Runs handed to other processes (the MPI ranks of mc/mpi_campaign.hpp) from the same queue as
/// the local children: run_local calls serve() in its loop (non-blocking) and finish() at the end.
class RemoteWorkers {
 public:
  virtual ~RemoteWorkers() = default;
  using Next = std::function<std::optional<std::int64_t>()>;  // the next run to hand out, if any
  using Done = std::function<core::Result<bool>(const RunRecord&)>;
  /// Answers the requests that arrived: takes finished runs into `done`, hands out `next` ones.
  virtual core::Result<bool> serve(const Next& next, const Done& done) = 0;
  /// Runs handed out and not returned yet.
  [[nodiscard]] virtual std::int64_t outstanding() const = 0;
  /// Once no run is left: tells every remote worker to stop.
  virtual void finish() = 0;
};

/// Runs one run in a child process (time limit, crash isolation) and waits for it: the worker
/// side of a remote rank.
RunRecord run_isolated(const Campaign& campaign, const RunSpec& spec, const PoolOptions& options);

/// Runs the given run indices of `campaign` (time limit: campaign.time_limit_s each). Returns an
/// error only when `on_finished` does (the children still running are then killed) or a process
/// cannot be started. `progress` (optional) is called after each run and about once a second.
core::Result<bool> run_local(const Campaign& campaign, const std::vector<std::int64_t>& runs, const PoolOptions& options,
                             const RunSink& on_finished, const std::function<void(const PoolProgress&)>& progress = {},
                             RemoteWorkers* remote = nullptr);

}  // namespace visors::mc
