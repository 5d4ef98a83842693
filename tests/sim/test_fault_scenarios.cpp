// Shortened system tests of the fault scenarios of data/scenarios/faults: each run with the
// on-board GPS navigation, and the host's FDIR response that Guffanti et al., AAS 23-149, 2023,
// sec. 4.1, prescribes (GNC incapable -> role switch; non-GNC fault during a transfer -> role
// switch and back to standby; garbage refused and counted; a lost crosslink absorbed), passive
// safety throughout. Skipped without the GPS constellation's file (the data search path).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "visors/core/files/data_path.hpp"
#include "visors/core/files/text_file.hpp"
#include "support/white_receiver.hpp"
#include "visors/sim/campaign_simulation.hpp"

namespace visors::sim {
namespace {

struct FaultRun {
  nlohmann::json summary;
  std::string events;
};

std::string read(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

FaultRun run(const std::string& name) {
  const std::filesystem::path file = std::filesystem::path(VISORS_SOURCE_DIR) / "data/scenarios/faults" / (name + ".toml");
  const auto parsed = campaign_from_toml(read(file));
  EXPECT_TRUE(parsed.ok()) << file << ": " << (parsed.ok() ? "" : parsed.error().describe());
  auto scenario = parsed.value();
  // The FDIR's figures under white receiver noise: the real sky's navigation is measured apart.
  visors::test::use_white_receiver(scenario.gnss.receiver);
  visors::test::tell_the_filter_white(scenario);
  const auto dir = std::filesystem::temp_directory_path() / ("visors_fault_" + std::to_string(::getpid()) + "_" + name);
  const auto result = run_campaign(scenario, dir);
  EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().describe());
  FaultRun out;
  if (result.ok()) out.summary = result->summary;
  out.events = read(dir / "events.csv");
  std::filesystem::remove_all(dir);
  return out;
}

class FaultScenario : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!core::files::find_data_file(GnssSettings{}.nav_file)) GTEST_FAIL() << "the GPS navigation file is not in the data search path";
  }
  static void expect_safe(const FaultRun& r) {
    EXPECT_EQ(r.summary["safety_violations"].get<int>(), 0);
    EXPECT_GT(r.summary["min_separation_rn_m"].get<double>(), r.summary["requirements"]["safety_epsilon_m"].get<double>());
  }
};

// The active OSC loses GPS: incapable after its solution ages past 10 s, roles switched 60 s later.
TEST_F(FaultScenario, GpsOutageOfTheActiveSpacecraftSwitchesRoles) {
  const FaultRun r = run("gps_outage");
  EXPECT_NE(r.events.find("600,osc,fault,\"GPS receiver outage"), std::string::npos) << r.events;
  EXPECT_NE(r.events.find("670,sim,fdir,\"osc GNC incapable: role switch\""), std::string::npos) << r.events;
  expect_safe(r);
  EXPECT_EQ(r.summary["final_mode"], "standby");
  // The OSC's 600 s without a receiver epoch count as not fixed in the fix rate over all epochs;
  // the DSC's receiver measured throughout (alone then: the OSC sent nothing).
  const auto& osc = r.summary["navigation"]["osc"];
  EXPECT_NEAR(osc["receiver_time_tags"].get<double>() - osc["epochs_processed"].get<double>(), 600.0, 2.0);
  EXPECT_NEAR(osc["fix_rate_all_epochs"].get<double>(),
              osc["fix_rate"].get<double>() * osc["epochs_processed"].get<double>() / osc["receiver_time_tags"].get<double>(), 1e-12);
  EXPECT_LT(osc["fix_rate_all_epochs"].get<double>(), osc["fix_rate"].get<double>() - 0.2);
  const auto& dsc = r.summary["navigation"]["dsc"];
  EXPECT_NEAR(dsc["receiver_time_tags"].get<double>(), dsc["epochs_processed"].get<double>(), 1.0);
}

// Both filters go on alone and fix again afterwards; nobody is declared incapable.
TEST_F(FaultScenario, CrosslinkLossIsAbsorbed) {
  const FaultRun r = run("crosslink_loss");
  EXPECT_EQ(r.events.find("fdir"), std::string::npos) << r.events;
  for (const char* craft : {"dsc", "osc"}) {
    const auto& nav = r.summary["navigation"][craft];
    EXPECT_NEAR(nav["epochs_alone"].get<double>(), 600.0, 5.0) << craft;
    EXPECT_GE(nav["fix_rate"].get<double>(), 0.7) << craft;  // the 600 s alone are float or held
    EXPECT_EQ(nav["wrong_fix_epochs"].get<int>(), 0) << craft;
  }
  expect_safe(r);
}

// Every garbage record refused: those of the 7 input channels for their checksum, those of the
// 4 output channels as the wrong channel (an input interface never decodes them); every NaN
// record's values rejected; the navigation and the modes go on as without it.
TEST_F(FaultScenario, GarbageIsRefusedAndCounted) {
  const FaultRun r = run("garbage");
  for (const char* craft : {"dsc", "osc"}) {
    EXPECT_EQ(r.summary["inputs_refused"][craft]["by_reason"]["bad_checksum"].get<int>(), 600 * 7) << craft;
    EXPECT_EQ(r.summary["inputs_refused"][craft]["by_reason"]["wrong_channel"].get<int>(), 600 * 4) << craft;
    EXPECT_GE(r.summary["navigation"][craft]["fix_rate_after_first_fix"].get<double>(), 0.995) << craft;
    EXPECT_EQ(r.summary["navigation"][craft]["epochs_alone"].get<int>(), 0) << craft;
  }
  EXPECT_GE(r.summary["rejected_inputs"].get<int>(), 2 * 600 * 6);
  EXPECT_EQ(r.events.find("fdir"), std::string::npos);
  expect_safe(r);
}

// The active OSC's bus in safe mode during the transfer: roles switched, the DSC back towards
// standby, the OSC passive when it returns, no switch back to a spacecraft in safe mode.
TEST_F(FaultScenario, SafeModeOfTheActiveSpacecraftSwitchesRolesAndReturnsTowardsStandby) {
  const FaultRun r = run("safe_mode");
  EXPECT_NE(r.events.find("3000,sim,fdir,\"osc in bus safe mode: role switch, then transfer to standby\""), std::string::npos)
      << r.events;
  EXPECT_NE(r.events.find("3001,dsc,mode,\"transfer_to_science -> transfer_to_standby\""), std::string::npos);
  EXPECT_NE(r.events.find("back from bus safe mode: made passive"), std::string::npos);
  EXPECT_EQ(r.events.find("GNC incapable: role switch"), std::string::npos);
  EXPECT_GT(r.summary["delta_v_mps"]["dsc"]["transfer_to_standby"].get<double>(), 0.0);
  expect_safe(r);
}

// The active OSC's thruster fails in the transfer: at its first refused maneuver the host
// switches roles and sends the DSC back to standby, which it flies.
TEST_F(FaultScenario, ThrusterFailureSwitchesRolesAndReturnsTowardsStandby) {
  const FaultRun r = run("thruster_failure");
  EXPECT_NE(r.events.find("3000,osc,fault,\"thruster failed\""), std::string::npos) << r.events;
  EXPECT_NE(r.events.find("sim,fdir,\"osc thruster failed: role switch, then transfer to standby\""), std::string::npos);
  EXPECT_NE(r.events.find("dsc,mode,\"transfer_to_science -> transfer_to_standby\""), std::string::npos);
  EXPECT_GT(r.summary["delta_v_mps"]["dsc"]["transfer_to_standby"].get<double>(), 0.0);
  expect_safe(r);
}

// A 1-ms receiver clock jump of the active OSC: both filters take it into the OSC's clock state
// at once (each sees it once: as its own receiver's, or the other's) and stay fixed.
TEST_F(FaultScenario, ReceiverClockJumpIsAbsorbed) {
  const FaultRun r = run("clock_jump");
  for (const char* craft : {"dsc", "osc"}) {
    const auto& nav = r.summary["navigation"][craft];
    EXPECT_EQ(nav["clock_jumps"].get<int>(), 1) << craft;
    EXPECT_GE(nav["fix_rate_after_first_fix"].get<double>(), 0.995) << craft;
    EXPECT_EQ(nav["wrong_fix_epochs"].get<int>(), 0) << craft;
    EXPECT_LT(nav["outside_slews"]["relative_antenna_worst_m"].get<double>(), 0.01) << craft;
  }
  EXPECT_EQ(r.events.find("fdir"), std::string::npos);
  expect_safe(r);
}

}  // namespace
}  // namespace visors::sim
