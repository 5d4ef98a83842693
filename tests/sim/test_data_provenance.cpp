// sim/data_provenance: the FNV-1a 64 checksum against the published test vectors (Fowler, Noll &
// Vo, "FNV hash" test suite: "" -> cbf29ce484222325, "a" -> af63dc4c8601ec8c, "foobar" ->
// 85944171f73967e8), sizes, and a scenario's files found or not.
#include "visors/sim/data_provenance.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace visors::sim {
namespace {

std::string checksum_of(const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / ("visors_fnv_" + std::to_string(::getpid()));
  std::ofstream(path, std::ios::binary) << bytes;
  const auto use = describe_data_file(path);
  std::filesystem::remove(path);
  return use.ok() ? use->checksum + "/" + std::to_string(use->size) : use.error().message;
}

TEST(DataProvenance, EmptyFileHasTheOffsetBasis) { EXPECT_EQ(checksum_of(""), "cbf29ce484222325/0"); }
TEST(DataProvenance, OneLetter) { EXPECT_EQ(checksum_of("a"), "af63dc4c8601ec8c/1"); }
TEST(DataProvenance, Foobar) { EXPECT_EQ(checksum_of("foobar"), "85944171f73967e8/6"); }

TEST(DataProvenance, AMissingFileIsAnError) {
  EXPECT_FALSE(describe_data_file("/nonexistent/visors/file").ok());
}

TEST(DataProvenance, AMissingScenarioFileIsListedWithoutAPath) {
  CampaignScenario s = default_campaign();
  s.gnss.nav_file = "gnss/absent_for_the_test.rnx";
  const auto files = data_files_of(s);
  ASSERT_FALSE(files.empty());
  EXPECT_EQ(files.front().key + "|" + files.front().path, "gnss.nav_file|");
}

}  // namespace
}  // namespace visors::sim
