#pragma once
// The durable results of a Monte Carlo campaign: one SQLite file (WAL journal), one transaction per
// finished run, so a campaign killed at any instant (kill -9, a lost node) keeps every run it
// stored and none half-stored; `visors mc --resume` then runs only the missing ones. The schema
// (docs/monte-carlo.md):
//   campaign      the campaign file, its base scenario file as read and as resolved (with `set`),
//                 the program version
//   data_files    the data files the base scenario found: path, size, FNV-1a 64 checksum
//   runs          index, sweep key and value, replicate, seed, drawn parameters (JSON), status,
//                 error text, wall time and the run's timings (JSON), finish time
//   observations  per attempt: time, lateral and focus errors, lateral velocity, the lateral error
//                 in the detector's frame and the signed focus error, success
//   summaries     per finished run: success rate, delta-v, separations, safety, navigation, and
//                 the whole summary.json less its timings
// Only `runs.wall_s`, `runs.timings` and `runs.finished_utc` depend on the host: the rest is the
// same whatever the number of threads, processes or ranks, and across a kill and a resume.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/mc/campaign_file.hpp"
#include "visors/mc/run_record.hpp"
#include "visors/mc/sqlite_database.hpp"
#include "visors/sim/data_provenance.hpp"

namespace visors::mc {

using sim::DataFileUse;

struct StoredRun {
  std::int64_t run = 0;
  std::string sweep_key;       // empty without sweeps
  double sweep_value = 0.0;    // NaN for a non-numeric value
  std::string sweep_value_text;
  std::int64_t replicate = 0;
  std::int64_t seed = 0;
  bool ok = false;
  double wall_s = 0.0;
  std::string error;
  nlohmann::json parameters;
  nlohmann::json summary;      // null for a failed run
};

struct CampaignInfo {
  std::string name, program_version, created_utc;
  std::int64_t total_runs = 0;
  std::vector<DataFileUse> data_files;
};

class ResultsStore {
 public:
  static core::Result<ResultsStore> open(const std::filesystem::path& path);

  /// A new store records the campaign; an existing one must hold the same campaign file (else an
  /// error: resuming into another campaign's results would mix them).
  core::Result<bool> record_campaign(const Campaign& campaign, const std::string& base_scenario_toml,
                                     const std::vector<DataFileUse>& data_files);
  /// The campaign file's text and its base scenario's text as recorded (`visors mc rerun` runs
  /// from these, not from the files as they are now).
  core::Result<std::pair<std::string, std::string>> campaign_file() const;
  /// Indices of the runs stored, ascending.
  core::Result<std::vector<std::int64_t>> stored_runs();
  /// Stores a finished run (its observations and summary when ok) in one transaction.
  core::Result<bool> store(const RunSpec& spec, const RunRecord& record);
  core::Result<std::vector<StoredRun>> runs();
  core::Result<CampaignInfo> info();

 private:
  explicit ResultsStore(SqlDatabase db) : db_(std::move(db)) {}
  core::Result<bool> insert_campaign(const Campaign& campaign, const std::string& base_scenario_toml,
                                     const std::vector<DataFileUse>& data_files);
  core::Result<bool> insert_run(const RunSpec& spec, const RunRecord& record);
  core::Result<bool> insert_observations(const RunRecord& record);
  core::Result<bool> insert_summary(const RunRecord& record);
  mutable SqlDatabase db_;
};

/// A run's summary less its host-dependent timings (what `summaries.summary` stores).
nlohmann::json without_timings(const nlohmann::json& summary);

/// The program's version ("visors <version>").
std::string program_version();

}  // namespace visors::mc
