// `visors baseline` end to end: the outputs of a run on the GSI pair (data/, found
// through the data search path; the processing itself is checked in tests/baseline), and bad
// input that must exit 2 with a message naming the option or the file and line.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "visors/core/files/data_path.hpp"
#include "gnss/gnss_test_data.hpp"
#include "run_tool.hpp"
#include "support/temp_file.hpp"

namespace visors::test {
namespace {

const std::string kDir = "gnss/gsi-2005-04-02/";
const std::string kBase = " --base-ecef -3978241.958 3382840.234 3649900.853";

bool have_gsi() { return core::files::find_data_file(kDir + "07590920.05o").has_value(); }

std::string gsi_args(const std::string& extra) {
  return "baseline " + kDir + "07590920.05o " + kDir + "30400920.05o --nav " + kDir + "07590920.05n --nav " + kDir +
         "30400920.05n" + kBase + " " + extra;
}

TEST(BaselineCommand, WritesCsvSummaryAndPage) {
  if (!have_gsi()) GTEST_FAIL() << "gnss/gsi-2005-04-02 not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
  const TempDir dir;
  const auto run = run_visors(gsi_args("--out " + dir.path().string()));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto summary = nlohmann::json::parse(file_text(dir.path() / "summary.json"));
  EXPECT_EQ(summary["epochs"]["paired"], 120);  // the files' 120 common epochs
  const auto& st = summary["statistics"]["epochs_per_status"];
  EXPECT_EQ(st["fix"].get<int>() + st["partial"].get<int>() + st["float"].get<int>() + st["code"].get<int>() +
                st["none"].get<int>(),
            120);
  std::istringstream csv(file_text(dir.path() / "baseline.csv"));
  int lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, 121);  // header + one row per paired epoch
  EXPECT_NE(file_text(dir.path() / "baseline.html").find("<svg"), std::string::npos);
}

TEST(BaselineCommand, UnknownModeNamesTheOption) {
  const auto run = run_visors(gsi_args("--mode moving --out /tmp/visors-never"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--mode"), std::string::npos) << run.err;
}

TEST(BaselineCommand, BaseFarFromTheEarthIsRejected) {
  const auto run = run_visors("baseline a.obs b.obs --nav c.nav --base-ecef 0 0 0");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--base-ecef"), std::string::npos) << run.err;
}

TEST(BaselineCommand, ElevationMaskOutOfRangeIsRejected) {
  const auto run = run_visors(gsi_args("--elevation-mask 95"));
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("elevation_mask"), std::string::npos) << run.err;
}

TEST(BaselineCommand, MissingObservationFileIsNamed) {
  const auto run = run_visors("baseline /nonexistent/rover.obs /nonexistent/base.obs --nav x.nav" + kBase);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("/nonexistent/rover.obs"), std::string::npos) << run.err;
}

TEST(BaselineCommand, MalformedObservationFileNamesTheLine) {
  if (!have_gsi()) GTEST_FAIL() << "gnss/gsi-2005-04-02 not found in data/ nor VISORS_DATA_PATH (data/SOURCES.md)";
  const TempDir dir;
  const auto original = core::files::find_data_file(kDir + "07590920.05o").value();
  std::istringstream in(file_text(original));
  std::ofstream out(dir.path() / "bad.05o");
  int k = 0;
  for (std::string line; std::getline(in, line);) out << (++k == 20 ? "  garbage that is not a number" : line) << "\n";
  out.close();
  const auto run = run_visors("baseline " + (dir.path() / "bad.05o").string() + " " + kDir + "30400920.05o --nav " +
                              kDir + "07590920.05n" + kBase + " --out " + dir.path().string());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("bad.05o:20"), std::string::npos) << run.err;
}

}  // namespace
}  // namespace visors::test
