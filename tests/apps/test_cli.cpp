// The CLI's own contract: unknown tools and malformed JSON are rejected with exit code 2 and a
// one-line message (the `visors tool` contract: docs/cli/tool.md).
#include <gtest/gtest.h>

#include "apps/run_tool.hpp"

namespace {

TEST(Cli, UnknownToolIsRejectedWithExitCode2) {
  const auto run = visors::test::run_tool("no-such-tool", "{}");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(Cli, UnknownToolMessageNamesTheTool) {
  const auto run = visors::test::run_tool("no-such-tool", "{}");
  EXPECT_NE(run.err.find("no-such-tool"), std::string::npos) << run.err;
}

TEST(Cli, MalformedJsonIsRejectedWithExitCode2) {
  const auto run = visors::test::run_tool("elements", "{\"r\": [1, 2");
  EXPECT_EQ(run.exit_code, 2);
}

// A number beyond double range is an out_of_range error of the JSON parser, not a syntax error:
// it must still be a bad-input exit, not an abort.
TEST(Cli, OutOfRangeNumberIsRejectedWithExitCode2) {
  const auto run = visors::test::run_tool("elements", "{\"r\": [1e999, 0, 0]}");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(Cli, NonObjectJsonIsRejected) {
  const auto run = visors::test::run_tool("elements", "[1, 2, 3]");
  EXPECT_EQ(run.exit_code, 2);
}

TEST(Cli, ErrorMessageIsOneLine) {
  const auto run = visors::test::run_tool("elements", "{\"r\": [1, 2");
  ASSERT_FALSE(run.err.empty());
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

}  // namespace
