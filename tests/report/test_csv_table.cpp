// The run-directory CSV reader: quoting, missing values, strict numbers, and errors that name
// the file, the line and the column.

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "visors/report/csv_table.hpp"
#include "visors/report/run_data.hpp"
#include "visors/report/run_directory.hpp"
#include "support/temp_file.hpp"
#include "synthetic_run.hpp"

namespace visors::report {
namespace {

TEST(CsvTable, ReadsQuotedFieldsAndMissingValues) {
  const test::TempFile file(
      "t_s,kind,detail\r\n"
      "1.5,mode,\"a, b\"\r\n"
      "\n"
      ",fdir,\"said \"\"hi\"\"\nover two lines\"\n"
      "3e2,plan,plain\n",
      ".csv");
  const auto table = CsvTable::read(file.path());
  ASSERT_TRUE(table.ok()) << table.error().describe();
  ASSERT_EQ(table->row_count(), 3u);
  EXPECT_EQ(table->line(0), 2u);
  EXPECT_EQ(table->line(1), 4u);
  EXPECT_EQ(table->line(2), 6u);  // the quoted line break counts
  const auto detail = table->texts("detail");
  ASSERT_TRUE(detail.ok());
  EXPECT_EQ(detail.value()[0], "a, b");
  EXPECT_EQ(detail.value()[1], "said \"hi\"\nover two lines");
  EXPECT_EQ(detail.value()[2], "plain");
  const auto t = table->numbers("t_s");
  ASSERT_TRUE(t.ok()) << t.error().describe();
  EXPECT_EQ(t.value()[0], 1.5);
  EXPECT_TRUE(std::isnan(t.value()[1]));  // empty cell = missing value
  EXPECT_EQ(t.value()[2], 300.0);
}

TEST(CsvTable, MalformedNumberNamesFileLineAndColumn) {
  const test::TempFile file("t_s,sep_rn_m\n0,1.0\n10,1.0x\n", ".csv");
  const auto table = CsvTable::read(file.path());
  ASSERT_TRUE(table.ok());
  const auto sep = table->numbers("sep_rn_m");
  ASSERT_FALSE(sep.ok());
  const std::string message = sep.error().describe();
  EXPECT_NE(message.find(file.path().string()), std::string::npos) << message;
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
  EXPECT_NE(message.find("column 'sep_rn_m'"), std::string::npos) << message;
  EXPECT_NE(message.find("1.0x"), std::string::npos) << message;
}

TEST(CsvTable, RejectsNonFiniteAndPaddedNumbers) {
  EXPECT_FALSE(parse_cell_number("nan").has_value());
  EXPECT_FALSE(parse_cell_number("inf").has_value());
  EXPECT_FALSE(parse_cell_number(" 1").has_value());
  EXPECT_FALSE(parse_cell_number("1e999").has_value());
  EXPECT_TRUE(std::isnan(*parse_cell_number("")));
  EXPECT_EQ(*parse_cell_number("-2.5e-3"), -2.5e-3);
}

TEST(CsvTable, MissingFileIsNamed) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "visors_no_such_file_12345.csv";
  const auto table = CsvTable::read(path);
  ASSERT_FALSE(table.ok());
  EXPECT_NE(table.error().describe().find(path.string()), std::string::npos) << table.error().describe();
}

TEST(CsvTable, WrongFieldCountAndUnterminatedQuoteNameTheLine) {
  const test::TempFile short_row("a,b\n1,2\n3\n", ".csv");
  const auto a = CsvTable::read(short_row.path());
  ASSERT_FALSE(a.ok());
  EXPECT_NE(a.error().describe().find("line 3"), std::string::npos) << a.error().describe();
  const test::TempFile open_quote("a,b\n1,\"2\n", ".csv");
  const auto b = CsvTable::read(open_quote.path());
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.error().describe().find("line 2"), std::string::npos) << b.error().describe();
}

TEST(CsvTable, MissingColumnIsNamed) {
  const test::TempFile file("t_s,mode\n0,standby\n", ".csv");
  const auto table = CsvTable::read(file.path());
  ASSERT_TRUE(table.ok());
  const auto error = table->require_columns(kTimeseriesColumns);
  ASSERT_TRUE(error.has_value());
  EXPECT_NE(error->describe().find("'active'"), std::string::npos) << error->describe();
}

TEST(RunData, LoadsTheSyntheticRun) {
  const test::SyntheticRun run;
  const auto data = load_run(run.dir());
  ASSERT_TRUE(data.ok()) << data.error().describe();
  EXPECT_EQ(data->timeseries.size(), run.rows());
  EXPECT_EQ(data->observations.size(), 4u);
  EXPECT_FALSE(data->observations[1].success);
  EXPECT_EQ(data->events.size(), 5u);
  EXPECT_NE(data->events[3].detail.find("<script>"), std::string::npos);
  EXPECT_TRUE(std::isnan(data->timeseries.safety_margin.front()));
  EXPECT_TRUE(std::isfinite(data->timeseries.safety_margin.back()));
}

TEST(RunData, BadCellInTimeseriesNamesLineAndColumn) {
  const test::SyntheticRun run;
  const std::filesystem::path path = run.dir() / kTimeseriesFile;
  std::ifstream in(path);
  std::string header, first, rest;
  std::getline(in, header);
  std::getline(in, first);
  rest.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  in.close();
  // The 4th column is ada_mean_m: corrupt it on line 2.
  std::size_t comma = 0;
  for (int i = 0; i < 3; ++i) comma = first.find(',', comma) + 1;
  first.insert(comma, "x");
  std::ofstream(path) << header << '\n' << first << '\n' << rest;
  const auto data = load_run(run.dir());
  ASSERT_FALSE(data.ok());
  const std::string message = data.error().describe();
  EXPECT_NE(message.find("timeseries.csv line 2 column 'ada_mean_m'"), std::string::npos) << message;
}

TEST(RunData, EmptyTimeIsAnError) {
  const test::SyntheticRun run({.orbits = 0.2});
  const std::filesystem::path path = run.dir() / kTimeseriesFile;
  std::ifstream in(path);
  std::string header, first, rest;
  std::getline(in, header);
  std::getline(in, first);
  rest.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  in.close();
  std::ofstream(path) << header << '\n' << first.substr(first.find(',')) << '\n' << rest;
  const auto data = load_run(run.dir());
  ASSERT_FALSE(data.ok());
  EXPECT_NE(data.error().describe().find("line 2 column 't_s'"), std::string::npos) << data.error().describe();
}

}  // namespace
}  // namespace visors::report
