#pragma once
// A CSV table of a run directory (docs/run-directory.md) read whole into memory: a header line,
// then records. Unlike core::files::read_csv_columns it understands RFC 4180 quoting, because the
// `detail` column of events.csv is free text that may hold commas, quotes and line breaks.
// Cells are looked up by header name, so the report does not depend on column order. Numbers are
// parsed strictly (the whole cell, finite); an empty cell is a missing value (NaN). Every error
// names the file, the line and the column.

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "visors/core/result.hpp"

namespace visors::report {

class CsvTable {
 public:
  /// Reads `path`. Errors: the file cannot be opened, an unterminated quote, a record whose field
  /// count differs from the header's. A file with no header line gives a table without columns.
  static core::Result<CsvTable> read(const std::filesystem::path& path);

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::size_t row_count() const { return rows_.size(); }
  [[nodiscard]] const std::vector<std::string>& header() const { return header_; }
  /// The index of column `name`, or nullopt.
  [[nodiscard]] std::optional<std::size_t> column(std::string_view name) const;
  /// An error naming the first of `names` the header lacks; nullopt when all are there.
  [[nodiscard]] std::optional<core::Error> require_columns(std::span<const std::string_view> names) const;

  /// The 1-based line of the file where data row `row` starts.
  [[nodiscard]] std::size_t line(std::size_t row) const { return rows_[row].line; }
  [[nodiscard]] const std::string& cell(std::size_t row, std::size_t column) const {
    return rows_[row].fields[column];
  }

  /// Column `name` as numbers (empty cell -> NaN). Errors: no such column, a cell that is not a
  /// finite number.
  [[nodiscard]] core::Result<std::vector<double>> numbers(std::string_view name) const;
  /// Column `name` as text.
  [[nodiscard]] core::Result<std::vector<std::string>> texts(std::string_view name) const;

  /// The error for `row`'s cell in column `name`: field "<file> line N column 'name'".
  [[nodiscard]] core::Error cell_error(std::size_t row, std::string_view name, std::string message) const;

 private:
  struct Row {
    std::size_t line = 0;
    std::vector<std::string> fields;
  };
  std::filesystem::path path_;
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

/// A strictly parsed cell: NaN for an empty cell, nullopt when the text is not a finite number.
std::optional<double> parse_cell_number(std::string_view text);

}  // namespace visors::report
