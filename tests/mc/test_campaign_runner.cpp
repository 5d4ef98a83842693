// mc/campaign_runner: a run that read other data than the campaign is stored failed with the
// reason, and a campaign does not resume on other data.
#include "visors/mc/campaign_runner.hpp"

#include <gtest/gtest.h>

#include "mc_test_campaign.hpp"

namespace visors::mc {
namespace {

const sim::DataFileUse kGravity{"forces.gravity.model", "gravity/GGM05S.gfc", "/data/gravity/GGM05S.gfc", 1000,
                                "00000000000000aa"};

// A run's summary.json with one data file entry, as sim/campaign_simulation writes it.
RunRecord run_with_file(const std::string& checksum, const std::string& path = kGravity.path) {
  nlohmann::json file = {{"key", kGravity.key}, {"name", kGravity.name}, {"bytes", 1000}, {"fnv1a64", checksum}};
  file["path"] = path.empty() ? nlohmann::json() : nlohmann::json(path);
  return RunRecord{3, true, 1.0, "", {{"data_files", nlohmann::json::array({file})}}};
}

TEST(CampaignRunner, ARunOnTheCampaignsDataIsKept) {
  EXPECT_TRUE(checked_data_files(run_with_file(kGravity.checksum), {kGravity}).ok);
}

// The same file somewhere else (an MPI rank's own data folder) is the same data.
TEST(CampaignRunner, TheSameChecksumAtAnotherPathIsKept) {
  EXPECT_TRUE(checked_data_files(run_with_file(kGravity.checksum, "/node7/data/GGM05S.gfc"), {kGravity}).ok);
}

TEST(CampaignRunner, AnotherChecksumFailsTheRun) {
  EXPECT_FALSE(checked_data_files(run_with_file("00000000000000bb"), {kGravity}).ok);
}

TEST(CampaignRunner, TheReasonNamesTheKeyAndBothChecksums) {
  const RunRecord r = checked_data_files(run_with_file("00000000000000bb"), {kGravity});
  EXPECT_EQ(r.error,
            "data file forces.gravity.model differs from the campaign's: /data/gravity/GGM05S.gfc (FNV-1a 64 "
            "00000000000000bb) here, /data/gravity/GGM05S.gfc (FNV-1a 64 00000000000000aa) for the campaign");
}

// Not found on the rank (an embedded default used instead) while the campaign found it.
TEST(CampaignRunner, AFileNotFoundByTheRunFailsIt) {
  const RunRecord r = checked_data_files(run_with_file("", ""), {kGravity});
  EXPECT_NE(r.error.find("not found here"), std::string::npos);
}

// A failed run is the store's shape: no summary.
TEST(CampaignRunner, AFailedRunHasNoSummary) {
  EXPECT_TRUE(checked_data_files(run_with_file("00000000000000bb"), {kGravity}).summary.is_null());
}

TEST(CampaignRunner, ARunThatFailedAlreadyIsLeftAsItIs) {
  const RunRecord failed{3, false, 1.0, "time limit exceeded", nullptr};
  EXPECT_EQ(checked_data_files(failed, {kGravity}).error, "time limit exceeded");
}

// The store began with a gravity file this machine does not have: resuming is refused before any
// run.
TEST(CampaignRunner, ResumingOnOtherDataIsRefused) {
  const auto dir = test::campaign_folder("other_data");
  const Campaign c = load_campaign((dir / "campaign.toml").string()).value();
  auto store = ResultsStore::open(dir / "db.sqlite").value();
  ASSERT_TRUE(store.record_campaign(c, "", {kGravity}).ok());
  const auto ran = run_into_store(c, store, PoolOptions{});
  std::filesystem::remove_all(dir);
  ASSERT_FALSE(ran.ok());
  EXPECT_EQ(ran.error().field, "data_files");
}

}  // namespace
}  // namespace visors::mc
