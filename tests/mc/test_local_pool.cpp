// The campaign runner on the local pool: the stored results are the same with 1 and 2 processes
// and after a kill -9 and a resume; a run that throws, crashes or outlives its time limit is a
// failed run with its reason, and the campaign goes on.
#include "visors/mc/campaign_runner.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <thread>

#include <sys/wait.h>
#include <unistd.h>

#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

constexpr const char* kEightRuns = R"(
name = "eight"
scenario = "base.toml"
seed = 11
runs_per_value = 4
time_limit_s = 120.0
[dispersions]
"propulsion.magnitude_sigma" = { uniform = { min = 0.01, max = 0.1 } }
[[sweep]]
key = "crosslink.delay_s"
values = [0.5, 1.0]
)";

// Runs the campaign in `dir` into dir/<name>.sqlite on `workers` processes.
core::Result<std::int64_t> run_into(const std::filesystem::path& dir, const std::string& name, int workers) {
  auto campaign = load_campaign((dir / "campaign.toml").string());
  if (!campaign.ok()) return campaign.error();
  auto opened = ResultsStore::open(dir / (name + ".sqlite"));
  if (!opened.ok()) return opened.error();
  ResultsStore store = std::move(opened).value();
  PoolOptions pool;
  pool.workers = workers;
  pool.scratch = dir / "runs";
  return run_into_store(*campaign, store, pool);
}

std::vector<StoredRun> stored(const std::filesystem::path& db) { return ResultsStore::open(db).value().runs().value(); }

TEST(LocalPool, OneAndTwoProcessesStoreTheSameResults) {
  const auto dir = test::campaign_folder("workers");
  ASSERT_TRUE(run_into(dir, "one", 1).ok());
  ASSERT_TRUE(run_into(dir, "two", 2).ok());
  const std::string one = test::database_content(dir / "one.sqlite");
  const std::string two = test::database_content(dir / "two.sqlite");
  std::filesystem::remove_all(dir);
  EXPECT_GT(one.size(), 1000U);
  EXPECT_EQ(one, two);
}

TEST(LocalPool, EveryRunOfTheCampaignIsStoredOnce) {
  const auto dir = test::campaign_folder("count");
  ASSERT_TRUE(run_into(dir, "db", 2).ok());
  const auto runs = stored(dir / "db.sqlite");
  std::filesystem::remove_all(dir);
  ASSERT_EQ(runs.size(), 4U);
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].run, static_cast<std::int64_t>(i));
}

TEST(LocalPool, AResumeOfACompleteStoreRunsNothing) {
  const auto dir = test::campaign_folder("complete");
  ASSERT_TRUE(run_into(dir, "db", 2).ok());
  const auto again = run_into(dir, "db", 2);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(again.value(), 0);
}

// kill -9 of the campaign (a forked copy of this test running it) once two runs are stored, then
// a resume: the same content as a campaign run without interruption.
TEST(LocalPool, KillNineThenResumeStoresWhatAnUninterruptedCampaignStores) {
  const auto dir = test::campaign_folder("kill", kEightRuns);
  ASSERT_TRUE(run_into(dir, "whole", 2).ok());
  const pid_t child = fork();
  if (child == 0) {
    (void)run_into(dir, "killed", 1);
    _exit(0);
  }
  std::size_t seen = 0;
  for (int i = 0; i < 6000 && seen < 2; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (std::filesystem::exists(dir / "killed.sqlite")) {
      if (auto opened = ResultsStore::open(dir / "killed.sqlite"); opened.ok()) {
        ResultsStore store = std::move(opened).value();
        if (auto runs = store.stored_runs(); runs.ok()) seen = runs->size();
      }
    }
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
  const auto before = stored(dir / "killed.sqlite").size();
  const auto resumed = run_into(dir, "killed", 2);
  const std::string whole = test::database_content(dir / "whole.sqlite");
  const std::string killed = test::database_content(dir / "killed.sqlite");
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(resumed.ok());
  EXPECT_LT(before, 8U);  // the kill came before the end
  EXPECT_EQ(whole, killed);
}

TEST(LocalPool, ResumingIntoAnotherCampaignsStoreIsRefused) {
  const auto dir = test::campaign_folder("other");
  ASSERT_TRUE(run_into(dir, "db", 2).ok());
  std::ofstream(dir / "campaign.toml") << kEightRuns;
  const auto again = run_into(dir, "db", 2);
  std::filesystem::remove_all(dir);
  EXPECT_EQ(again.error().field, "results");
}

// A failure injected into run 1 (VISORS_MC_INJECT, mc/run_record.hpp): its stored error.
std::string failure_of_run_1(const std::string& inject, double time_limit_s = 120.0) {
  std::string campaign = test::kTinyCampaign;
  campaign.replace(campaign.find("time_limit_s = 120.0"), 20, "time_limit_s = " + std::to_string(time_limit_s));
  const auto dir = test::campaign_folder("fail", campaign);
  setenv("VISORS_MC_INJECT", inject.c_str(), 1);
  const auto ran = run_into(dir, "db", 2);
  unsetenv("VISORS_MC_INJECT");
  const auto runs = stored(dir / "db.sqlite");
  std::filesystem::remove_all(dir);
  if (!ran.ok() || runs.size() != 4 || runs[1].ok || !runs[0].ok || !runs[2].ok || !runs[3].ok) return "unexpected";
  return runs[1].error;
}

TEST(LocalPool, ARunThatThrowsIsAFailedRunWithTheException) {
  EXPECT_NE(failure_of_run_1("throw@1").find("injected exception"), std::string::npos);
}

TEST(LocalPool, ARunThatCrashesIsAFailedRunWithTheSignal) {
  EXPECT_NE(failure_of_run_1("crash@1").find("crashed: signal 6"), std::string::npos);
}

TEST(LocalPool, ARunPastItsTimeLimitIsStoppedAndFailed) {
  EXPECT_NE(failure_of_run_1("hang@1", 3.0).find("time limit exceeded"), std::string::npos);
}

}  // namespace
}  // namespace visors::mc
