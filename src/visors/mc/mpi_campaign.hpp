#pragma once
// A campaign over MPI ranks (`mpirun -n K visors mc CAMPAIGN.toml`): rank 0 reads the campaign,
// keeps the results store and runs its share of the runs in child processes like the local pool;
// it also hands runs out one at a time to the other ranks as they ask (dynamic distribution, so
// nodes of unequal speed all stay busy) and stores what they send back. Ranks > 0 get the
// campaign's and base scenario's text from rank 0 (they need no copy of the files, only the data
// files on their VISORS_DATA_PATH), and run each run they are given in a child process (time
// limit and crash isolation as on rank 0). Results are those of the local pool: a run depends on
// its index alone.
//
// Messages (MPI_COMM_WORLD): worker -> 0, tag 1: the previous run's record as JSON text (empty at
// first): "give me the next"; 0 -> worker, tag 2: the next run index, or -1 to stop.
// Built when CMake finds MPI (Debian openmpi); without it, `visors mc` under mpirun says so.

#include <functional>
#include <memory>
#include <string>

#include "visors/core/result.hpp"
#include "visors/mc/campaign_file.hpp"
#include "visors/mc/local_pool.hpp"

namespace visors::mc {

/// Whether this build has MPI.
bool mpi_available();

/// Whether this process was started by an MPI launcher (OpenMPI's OMPI_COMM_WORLD_SIZE, or
/// PMI_SIZE of MPICH and Slurm).
bool launched_by_mpi();

class MpiSession {
 public:
  /// MPI_Init (errors: no MPI in this build).
  static core::Result<std::unique_ptr<MpiSession>> start();
  ~MpiSession();  // MPI_Finalize
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }

  /// Rank 0 sends, the others receive: the campaign file's and base scenario's text (empty texts
  /// when rank 0 could not read the campaign: the workers then stop).
  void share_campaign(std::string& campaign_text, std::string& scenario_text) const;

 private:
  MpiSession() = default;
  int rank_ = 0, size_ = 1;
};

/// Rank 0's view of the other ranks, for run_local.
std::unique_ptr<RemoteWorkers> mpi_remote_workers(const MpiSession& session);

/// A rank > 0: asks rank 0 for runs until told to stop; `execute` runs one (run_isolated: in a
/// child process).
void serve_as_worker(const MpiSession& session, const std::function<RunRecord(std::int64_t)>& execute);

}  // namespace visors::mc
