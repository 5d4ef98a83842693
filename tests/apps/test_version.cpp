// One version source: project(VERSION) in the top CMakeLists.txt, which the tests receive as
// VISORS_PROJECT_VERSION independently of the generated core/version.hpp the programs print.
#include <gtest/gtest.h>

#include <string>

#include "apps/run_tool.hpp"
#include "visors/core/version.hpp"

namespace {

TEST(Version, TheHeaderIsTheProjectVersion) { EXPECT_EQ(visors::core::kVersion, VISORS_PROJECT_VERSION); }

TEST(Version, TheFlagPrintsTheProjectVersion) {
  const auto r = visors::test::run_visors("--version");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, std::string("visors ") + VISORS_PROJECT_VERSION + "\n");
}

TEST(Version, TheSubcommandPrintsTheProjectVersion) {
  const auto r = visors::test::run_visors("version");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, std::string("visors ") + VISORS_PROJECT_VERSION + "\n");
}

}  // namespace
