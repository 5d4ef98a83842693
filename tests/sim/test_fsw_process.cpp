// The flight software as a process (`visors run --fsw process`: sim/flight_software.hpp,
// sim/fsw_process.hpp, apps/fsw/): both spacecraft's components as visors-fsw processes behind
// their records give the in-process run's results bit for bit, with CDGPS in the loop, maneuvers
// and the garbage fault's refused records on every channel; and a process that fails is an error
// saying why, not a hang or a crash.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include "visors/core/files/data_path.hpp"
#include "visors/gnc/files/flight_config_json.hpp"
#include "visors/sim/campaign_simulation.hpp"
#include "visors/sim/fsw_process.hpp"

namespace visors::sim {
namespace {

std::filesystem::path run_dir(const std::string& name) {
  return std::filesystem::temp_directory_path() / ("visors_fsw_" + std::to_string(::getpid()) + "_" + name);
}

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The summary without what differs by construction: the wall times and where the software ran.
nlohmann::json comparable_summary(const std::filesystem::path& dir) {
  nlohmann::json summary = nlohmann::json::parse(read(dir / "summary.json"));
  for (const char* key : {"wall_s", "flight_step_us", "flight_software"}) summary.erase(key);
  return summary;
}

bool have_gps_constellation() { return core::files::find_data_file(GnssSettings{}.nav_file).has_value(); }

// 30 min of the campaign with CDGPS: 10 min of standby with 2 min of the garbage fault, the
// science command, 20 min of the transfer to science (26 maneuvers): run once in process, once
// as two processes.
class FswProcessRun : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!have_gps_constellation()) return;
    const auto scenario = campaign_from_toml(R"(
[time]
max_duration_s = 1800.0
[campaign]
standby_s = 600.0
observations = 1
[navigation]
mode = "cdgps"
[fault]
garbage_t_s = 300.0
garbage_s = 120.0
)").value();
    in_process_ = run_dir("in_process");
    processes_ = run_dir("processes");
    auto a = run_campaign(scenario, in_process_);
    const RunOptions as_processes{.parallel_components = false, .fsw_command = {VISORS_FSW_BINARY}};
    auto b = run_campaign(scenario, processes_, {}, as_processes);
    ok_ = a.ok() && b.ok();
    if (!b.ok()) error_ = b.error().describe();
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(in_process_);
    std::filesystem::remove_all(processes_);
  }
  void SetUp() override {
    if (!have_gps_constellation()) GTEST_FAIL() << "the GPS navigation file is not in the data search path";
    ASSERT_TRUE(ok_) << error_;
  }
  static bool same_file(const char* name) { return read(in_process_ / name) == read(processes_ / name); }

  static inline std::filesystem::path in_process_, processes_;
  static inline bool ok_ = false;
  static inline std::string error_;
};

TEST_F(FswProcessRun, TheTimeSeriesAreTheSame) { EXPECT_TRUE(same_file("timeseries.csv")); }
TEST_F(FswProcessRun, TheNavigationIsTheSame) { EXPECT_TRUE(same_file("navigation.csv")); }
TEST_F(FswProcessRun, TheEventLogsAreTheSame) { EXPECT_TRUE(same_file("events.csv")); }
TEST_F(FswProcessRun, TheSummariesAreTheSameButForTheWallTimes) {
  EXPECT_EQ(comparable_summary(in_process_).dump(2), comparable_summary(processes_).dump(2));
}

// What makes the comparison mean something: maneuvers, navigation rows and refused records.
TEST_F(FswProcessRun, TheRunManeuveredNavigatedAndRefusedGarbage) {
  const nlohmann::json summary = comparable_summary(processes_);
  const std::string navigation = read(processes_ / "navigation.csv");
  EXPECT_NE(read(processes_ / "events.csv").find("maneuver"), std::string::npos);
  EXPECT_GT(std::count(navigation.begin(), navigation.end(), '\n'), 100);
  EXPECT_GT(summary["inputs_refused"]["dsc"]["by_reason"]["bad_checksum"].get<int>(), 100);
}

TEST_F(FswProcessRun, TheSummarySaysWhereTheSoftwareRan) {
  const nlohmann::json summary = nlohmann::json::parse(read(processes_ / "summary.json"));
  EXPECT_EQ(summary["flight_software"], std::string("process: ") + VISORS_FSW_BINARY);
}

// Each process ended with the end of its input and said what it did.
TEST_F(FswProcessRun, EachProcessLogsItsStepsAtTheEnd) {
  const std::string log = read(processes_ / "fsw_dsc.log");
  EXPECT_NE(log.find("visors-fsw dsc: 1801 steps"), std::string::npos) << log;
}

// Failures: each an error naming the spacecraft and what happened.
class FswProcessFailure : public ::testing::Test {
 protected:
  std::filesystem::path dir_ = run_dir("failure");
  void SetUp() override { std::filesystem::create_directories(dir_); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  core::Result<FswProcess> start(const std::vector<std::string>& command, int timeout_ms = 30000) {
    return FswProcess::start(command, dir_ / "flight_config.json", "dsc", dir_ / "fsw_dsc.log", timeout_ms);
  }
};

TEST_F(FswProcessFailure, AProgramThatIsNotThereCannotStart) {
  const auto p = start({(dir_ / "no-such-program").string()});
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.error().field, "fsw.dsc");
  EXPECT_NE(p.error().message.find("cannot start"), std::string::npos) << p.error().message;
}

// A missing configuration: visors-fsw exits 2 before it is ready, and its message is the error's.
TEST_F(FswProcessFailure, AMissingConfigurationStopsItWithItsMessage) {
  const auto p = start({VISORS_FSW_BINARY});
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("exit status 2"), std::string::npos) << p.error().message;
  EXPECT_NE(p.error().message.find("cannot be read"), std::string::npos) << p.error().message;
}

// A process that never answers is killed when the timeout runs out.
TEST_F(FswProcessFailure, AProcessThatNeverAnswersIsKilled) {
  const std::string script = (dir_ / "silent.sh").string();
  std::ofstream(script) << "#!/bin/sh\nexec sleep 30\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  const auto p = start({script}, 200);
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("killed"), std::string::npos) << p.error().message;
}

// A process that answers with what is no record of an output channel is refused.
TEST_F(FswProcessFailure, AnAnswerOfNoOutputChannelIsRefused) {
  const std::string script = (dir_ / "wrong.sh").string();
  std::ofstream(script) << "#!/bin/sh\nprintf '\\003\\000\\000\\000VG\\001'\n";
  std::filesystem::permissions(script, std::filesystem::perms::owner_all);
  const auto p = start({script});
  ASSERT_FALSE(p.ok());
  EXPECT_NE(p.error().message.find("no output channel"), std::string::npos) << p.error().message;
}

// A run whose flight software cannot start fails with the process's error.
TEST(FswProcessRunFailure, ARunWhoseFlightSoftwareCannotStartFails) {
  const auto scenario = campaign_from_toml("[campaign]\nstandby_s = 0.0\nobservations = 0\ntail_s = 10.0\n").value();
  const auto dir = run_dir("cannot_start");
  const RunOptions options{.parallel_components = false, .fsw_command = {(dir / "no-such-program").string()}};
  const auto result = run_campaign(scenario, dir, {}, options);
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.error().field, "fsw.dsc");
}

}  // namespace
}  // namespace visors::sim
