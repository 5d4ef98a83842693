#include "apps/mc/mc_command.hpp"

#include <algorithm>
#include <cstdio>
#include <chrono>
#include <memory>
#include <optional>
#include <filesystem>
#include <thread>
#include <unistd.h>

#include <fmt/core.h>

#include "visors/mc/campaign_file.hpp"
#include "visors/mc/campaign_report.hpp"
#include "visors/mc/campaign_runner.hpp"
#include "visors/mc/mpi_campaign.hpp"
#include "visors/mc/results_store.hpp"
#include "visors/mc/run_plan.hpp"
#include "visors/report/report.hpp"
#include "visors/sim/campaign_simulation.hpp"

namespace visors::mc_app {
namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitFailed = 1;

// On a terminal a refreshed line; in a log, a line a minute.
void print_progress(const mc::PoolProgress& p, bool terminal, double& last_line_s) {
  const double per_minute = p.wall_s > 0.0 ? 60.0 * static_cast<double>(p.finished) / p.wall_s : 0.0;
  const double eta_s = per_minute > 0.0 ? 60.0 * static_cast<double>(p.total - p.finished) / per_minute : 0.0;
  const std::string line = fmt::format("  runs {}/{} done, {} running, {} failed; {:.1f} runs/min; ETA {:.0f} min", p.finished,
                                       p.total, p.running, p.failed, per_minute, eta_s / 60.0);
  if (terminal) {
    fmt::print(stderr, "\r{}   ", line);
  } else if (p.wall_s - last_line_s >= 60.0 || p.finished == p.total) {
    fmt::print("{}\n", line);
    std::fflush(stdout);
    last_line_s = p.wall_s;
  }
}

// Success per sweep value over the stored runs (the figure's lower panel), on the terminal, in the
// campaign file's order.
void print_results(mc::ResultsStore& store) {
  auto runs = store.runs();
  if (!runs.ok()) return;
  long failed = 0;
  for (const mc::StoredRun& r : *runs) failed += r.ok ? 0 : 1;
  fmt::print("  {} runs stored, {} failed\n", runs->size(), failed);
  for (const mc::ValueSuccess& v : mc::success_by_value(*runs)) {
    const std::string what = v.key.empty() ? v.value : fmt::format("{} = {}", v.key, v.value);
    fmt::print("  {}: {} of {} attempts succeeded ({:.0f} %)\n", what, v.successes, v.attempts,
               v.attempts > 0 ? 100.0 * static_cast<double>(v.successes) / static_cast<double>(v.attempts) : 0.0);
  }
}

// A rank > 0 of an MPI campaign: the campaign from rank 0, then runs until told to stop.
int serve_rank(const mc::MpiSession& mpi, const McOptions& o) {
  std::string campaign_text, scenario_text;
  mpi.share_campaign(campaign_text, scenario_text);
  if (campaign_text.empty()) return kExitBadInput;  // rank 0 said why
  auto campaign = mc::campaign_from_toml(campaign_text, {}, scenario_text);
  mc::PoolOptions pool;
  pool.workers = 1;
  pool.scratch = std::filesystem::temp_directory_path() / fmt::format("visors-mc-rank{}-{}", mpi.rank(), ::getpid());
  pool.keep_runs = o.keep_runs;
  if (campaign.ok()) {
    if (auto base = mc::base_scenario(*campaign); base.ok()) mc::warm_caches(*base);
  }
  mc::serve_as_worker(mpi, [&](std::int64_t index) {
    if (campaign.ok()) return mc::run_isolated(*campaign, mc::run_spec(*campaign, index), pool);
    mc::RunRecord failed;  // not expected: rank 0 read the same texts
    failed.run = index;
    failed.error = fmt::format("rank {}: {}", mpi.rank(), campaign.error().describe());
    return failed;
  });
  std::error_code ignored;
  if (!o.keep_runs) std::filesystem::remove_all(pool.scratch, ignored);
  return 0;
}

// Rank 0 (or the only process): the campaign into its store, with the other ranks when any.
int coordinate(const McOptions& o, const mc::MpiSession* mpi) {
  std::string shared_campaign, shared_scenario;  // stay empty on an error: the other ranks stop
  const auto share = [&] {
    if (mpi != nullptr) mpi->share_campaign(shared_campaign, shared_scenario);
  };
  auto campaign = mc::load_campaign(o.campaign);
  if (!campaign.ok()) {
    fmt::print(stderr, "visors mc: {}: {}\n", o.campaign, campaign.error().describe());
    share();
    return kExitBadInput;
  }
  const std::filesystem::path out = o.out.empty() ? std::filesystem::path("out/mc") / campaign->name : std::filesystem::path(o.out);
  const std::filesystem::path database = out / "results.sqlite";
  if (std::filesystem::exists(database) && !o.resume) {
    fmt::print(stderr, "visors mc: {} exists: --resume to go on with it, or another --out\n", database.string());
    share();
    return kExitBadInput;
  }
  std::filesystem::create_directories(out);
  auto opened = mc::ResultsStore::open(database);
  if (!opened.ok()) {
    fmt::print(stderr, "visors mc: {}\n", opened.error().describe());
    share();
    return kExitFailed;
  }
  shared_campaign = campaign->text;
  shared_scenario = campaign->scenario_text;
  share();
  mc::ResultsStore store = std::move(opened).value();
  mc::PoolOptions pool;
  pool.workers = o.threads > 0 ? o.threads : static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  pool.scratch = out / "runs";
  pool.keep_runs = o.keep_runs;
  const int ranks = mpi != nullptr ? mpi->size() : 1;
  fmt::print("visors mc: {} ({}), {} runs, {} at a time{}, results {}\n", campaign->name, o.campaign, campaign->total_runs(),
             pool.workers, ranks > 1 ? fmt::format(" here and {} more MPI ranks", ranks - 1) : "", database.string());
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  mc::RunnerHooks hooks;
  double last_line_s = 0.0;
  hooks.progress = [&](const mc::PoolProgress& p) { print_progress(p, terminal, last_line_s); };
  hooks.stored = [&](const mc::RunSpec& spec, const mc::RunRecord& record) {
    if (record.ok) return;
    if (terminal) fmt::print(stderr, "\r");
    fmt::print("  run {} failed: {}\n", spec.index, record.error);
  };
  const auto remote = ranks > 1 ? mc::mpi_remote_workers(*mpi) : nullptr;
  const auto start = std::chrono::steady_clock::now();
  auto ran = mc::run_into_store(*campaign, store, pool, hooks, remote.get());
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (terminal) fmt::print(stderr, "\n");
  if (!ran.ok()) {
    fmt::print(stderr, "visors mc: {}\n", ran.error().describe());
    return ran.error().field == "results" ? kExitBadInput : kExitFailed;
  }
  fmt::print("  {} runs run this time in {:.1f} s ({:.0f} runs per hour)\n", *ran, wall_s,
             wall_s > 0.0 ? 3600.0 * static_cast<double>(*ran) / wall_s : 0.0);
  print_results(store);
  fmt::print("  results {}\n", database.string());
  return 0;
}

}  // namespace

int run_mc_command(const McOptions& o) {
  std::unique_ptr<mc::MpiSession> mpi;
  if (mc::launched_by_mpi()) {
    auto session = mc::MpiSession::start();
    if (!session.ok()) {
      fmt::print(stderr, "visors mc: {}\n", session.error().describe());
      return kExitBadInput;
    }
    mpi = std::move(session).value();
    if (mpi->rank() > 0) return serve_rank(*mpi, o);
  }
  return coordinate(o, mpi.get());
}

namespace {

// The results database at `path`, which must exist; nullopt after saying why, with the exit code.
std::optional<mc::ResultsStore> open_existing_store(const std::string& path, const char* command, int& exit_code) {
  if (!std::filesystem::exists(path)) {
    fmt::print(stderr, "{}: {}: no such results database\n", command, path);
    exit_code = kExitBadInput;
    return std::nullopt;
  }
  auto opened = mc::ResultsStore::open(path);
  if (!opened.ok()) {
    fmt::print(stderr, "{}: {}: {}\n", command, path, opened.error().describe());
    exit_code = kExitFailed;
    return std::nullopt;
  }
  return std::move(opened).value();
}

}  // namespace

int run_mc_rerun_command(const std::string& database, std::int64_t run, const std::string& out_dir) {
  int exit_code = 0;
  auto opened = open_existing_store(database, "visors mc rerun", exit_code);
  if (!opened) return exit_code;
  mc::ResultsStore& store = *opened;
  auto file = store.campaign_file();
  if (!file.ok()) {
    fmt::print(stderr, "visors mc rerun: {}: {}\n", database, file.error().describe());
    return kExitFailed;
  }
  auto campaign = mc::campaign_from_toml(file->first, {}, file->second);
  if (!campaign.ok()) {
    fmt::print(stderr, "visors mc rerun: the recorded campaign: {}\n", campaign.error().describe());
    return kExitBadInput;
  }
  if (run < 0 || run >= campaign->total_runs()) {
    fmt::print(stderr, "visors mc rerun: RUN: must be in [0, {}]\n", campaign->total_runs() - 1);
    return kExitBadInput;
  }
  const mc::RunSpec spec = mc::run_spec(*campaign, run);
  auto scenario = mc::scenario_for(*campaign, spec);
  if (!scenario.ok()) {
    fmt::print(stderr, "visors mc rerun: {}\n", scenario.error().describe());
    return kExitBadInput;
  }
  const std::string out = out_dir.empty() ? fmt::format("out/mc-rerun/run{:06d}", run) : out_dir;
  fmt::print("visors mc rerun: run {} of {} (seed {})\n", run, campaign->name, spec.seed);
  auto result = sim::run_campaign(*scenario, out, {}, sim::RunOptions{.parallel_components = true, .fsw_command = {}});
  if (!result.ok()) {
    fmt::print(stderr, "visors mc rerun: {}\n", result.error().describe());
    return kExitFailed;
  }
  auto report = report::write_report(result->dir);
  fmt::print("  success rate {:.0f} %\n", 100.0 * result->summary.value("success_rate", 0.0));
  if (auto runs = store.runs(); runs.ok()) {
    const auto stored = std::find_if(runs->begin(), runs->end(), [&](const mc::StoredRun& r) { return r.run == run; });
    if (stored == runs->end()) fmt::print("  not in the results database yet\n");
    else if (!stored->ok) fmt::print("  stored as failed: {}\n", stored->error);
    else fmt::print("  same results as stored: {}\n", mc::without_timings(result->summary) == stored->summary ? "yes" : "NO");
  }
  fmt::print("  run directory {}\n", result->dir.string());
  if (report.ok()) fmt::print("  report {}\n", report->string());
  return 0;
}

int run_mc_report_command(const std::string& database, const std::string& out_dir) {
  int exit_code = 0;
  auto opened = open_existing_store(database, "visors mc report", exit_code);
  if (!opened) return exit_code;
  mc::ResultsStore& store = *opened;
  const std::filesystem::path out = out_dir.empty() ? std::filesystem::path(database).parent_path() : std::filesystem::path(out_dir);
  auto written = mc::write_campaign_report(store, out);
  if (!written.ok()) {
    fmt::print(stderr, "visors mc report: {}\n", written.error().describe());
    return kExitFailed;
  }
  fmt::print("visors mc report: {}\n", written->string());
  return 0;
}

}  // namespace visors::mc_app
