// CSV tables by header name (core/files/csv_file.hpp), whole and row by row: the rows and columns
// asked for, in that order; the errors name the line.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "visors/core/files/csv_file.hpp"
#include "support/temp_file.hpp"

namespace visors::core::files {
namespace {

constexpr std::array<std::string_view, 2> kColumns = {"b", "a"};

TEST(CsvFile, ReadsTheAskedColumnsInTheirOrder) {
  const test::TempFile f("a,b,c\n1, 2,3\n\n4,5 ,6\n", ".csv");
  const auto rows = read_csv_columns(f.path(), kColumns, "table").value();
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].line, 4u);
  EXPECT_EQ(rows[1].fields, (std::vector<std::string>{"5", "4"}));
}

TEST(CsvFile, VisitsEachRowWithTheSameFields) {
  const test::TempFile f("a,b,c\n1, 2,3\n\n4,5 ,6\n", ".csv");
  std::vector<std::string> seen;
  ASSERT_TRUE(for_each_csv_row(f.path(), kColumns, "table", [&](std::size_t line, std::span<const std::string_view> fields) {
                seen.push_back(std::to_string(line) + ":" + std::string(fields[0]) + "," + std::string(fields[1]));
                return Result<bool>(true);
              }).ok());
  EXPECT_EQ(seen, (std::vector<std::string>{"2:2,1", "4:5,4"}));
}

TEST(CsvFile, TheVisitorsErrorStopsTheReading) {
  const test::TempFile f("a,b\n1,2\n3,4\n5,6\n", ".csv");
  int calls = 0;
  const auto r = for_each_csv_row(f.path(), kColumns, "table", [&](std::size_t line, std::span<const std::string_view>) {
    ++calls;
    return line == 3 ? Result<bool>(Error{"line 3", "bad"}) : Result<bool>(true);
  });
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().field, "line 3");
  EXPECT_EQ(calls, 2);
}

TEST(CsvFile, NamesTheMissingColumn) {
  const test::TempFile f("a,c\n1,2\n", ".csv");
  EXPECT_EQ(read_csv_columns(f.path(), kColumns, "table").error().field, "line 1");
}

TEST(CsvFile, NamesTheShortRow) {
  const test::TempFile f("a,b\n1,2\n3\n", ".csv");
  EXPECT_EQ(for_each_csv_row(f.path(), kColumns, "table", [](std::size_t, std::span<const std::string_view>) {
              return Result<bool>(true);
            }).error().field,
            "line 3");
}

}  // namespace
}  // namespace visors::core::files
