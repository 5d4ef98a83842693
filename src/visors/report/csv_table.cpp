#include "visors/report/csv_table.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>

#include "visors/core/files/csv_file.hpp"

namespace visors::report {
namespace {

// Splits the text of a whole file into records of fields, following RFC 4180: a field in double
// quotes may hold commas, line breaks and doubled quotes. A trailing '\r' (CRLF files) is dropped.
class RecordParser {
 public:
  explicit RecordParser(std::string_view text) : text_(text) {}

  [[nodiscard]] bool done() const { return pos_ >= text_.size(); }
  [[nodiscard]] std::size_t line() const { return line_; }

  // The next record; false with `error` set on an unterminated quote.
  bool next(std::vector<std::string>& fields, std::string& error) {
    fields.assign(1, std::string{});
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '\n') {
        ++line_;
        break;
      }
      if (c == ',') {
        fields.emplace_back();
      } else if (c == '"' && fields.back().empty()) {
        if (!read_quoted(fields.back())) {
          error = "unterminated quoted field";
          return false;
        }
      } else if (c != '\r' || (pos_ < text_.size() && text_[pos_] != '\n')) {
        fields.back().push_back(c);
      }
    }
    return true;
  }

 private:
  bool read_quoted(std::string& field) {
    while (pos_ < text_.size()) {
      const char c = text_[pos_++];
      if (c == '"') {
        if (pos_ < text_.size() && text_[pos_] == '"') {
          field.push_back('"');
          ++pos_;
          continue;
        }
        return true;
      }
      if (c == '\n') ++line_;
      field.push_back(c);
    }
    return false;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
};

bool blank(const std::vector<std::string>& fields) { return fields.size() == 1 && fields[0].empty(); }

}  // namespace

std::optional<double> parse_cell_number(std::string_view text) {
  if (text.empty()) return std::numeric_limits<double>::quiet_NaN();
  return core::files::parse_finite_number(text);
}

core::Result<CsvTable> CsvTable::read(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return core::Error{path.string(), "cannot be opened (missing file?)"};
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  CsvTable table;
  table.path_ = path;
  RecordParser parser(text);
  std::vector<std::string> fields;
  std::string error;
  while (!parser.done()) {
    const std::size_t start_line = parser.line();
    if (!parser.next(fields, error)) {
      return core::Error{path.string() + " line " + std::to_string(start_line), error};
    }
    if (blank(fields)) continue;  // blank lines carry nothing
    if (table.header_.empty()) {
      table.header_ = fields;
      continue;
    }
    if (fields.size() != table.header_.size()) {
      return core::Error{path.string() + " line " + std::to_string(start_line),
                         "has " + std::to_string(fields.size()) + " fields, the header " +
                             std::to_string(table.header_.size())};
    }
    table.rows_.push_back(Row{start_line, fields});
  }
  return table;
}

std::optional<std::size_t> CsvTable::column(std::string_view name) const {
  const auto it = std::find(header_.begin(), header_.end(), name);
  if (it == header_.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header_.begin());
}

std::optional<core::Error> CsvTable::require_columns(std::span<const std::string_view> names) const {
  for (const std::string_view name : names) {
    if (!column(name)) {
      return core::Error{path_.string() + " line 1", "header lacks column '" + std::string(name) + "'"};
    }
  }
  return std::nullopt;
}

core::Error CsvTable::cell_error(std::size_t row, std::string_view name, std::string message) const {
  return core::Error{path_.string() + " line " + std::to_string(rows_[row].line) + " column '" +
                         std::string(name) + "'",
                     std::move(message)};
}

core::Result<std::vector<double>> CsvTable::numbers(std::string_view name) const {
  const auto c = column(name);
  if (!c) return core::Error{path_.string() + " line 1", "header lacks column '" + std::string(name) + "'"};
  std::vector<double> values;
  values.reserve(rows_.size());
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const auto value = parse_cell_number(rows_[r].fields[*c]);
    if (!value) return cell_error(r, name, "'" + rows_[r].fields[*c] + "' is not a finite number");
    values.push_back(*value);
  }
  return values;
}

core::Result<std::vector<std::string>> CsvTable::texts(std::string_view name) const {
  const auto c = column(name);
  if (!c) return core::Error{path_.string() + " line 1", "header lacks column '" + std::string(name) + "'"};
  std::vector<std::string> values;
  values.reserve(rows_.size());
  for (const Row& row : rows_) values.push_back(row.fields[*c]);
  return values;
}

}  // namespace visors::report
