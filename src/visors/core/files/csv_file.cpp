#include "visors/core/files/csv_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

namespace visors::core::files {
namespace {

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    const std::size_t length = comma == std::string_view::npos ? std::string_view::npos : comma - start;
    fields.push_back(trimmed(line.substr(start, length)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

Error line_error(std::size_t line, std::string message) {
  return Error{"line " + std::to_string(line), std::move(message)};
}

std::optional<double> parse_finite_number(std::string_view text) {
  double value = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

Result<bool> for_each_csv_row(const std::filesystem::path& path, std::span<const std::string_view> columns,
                              const std::string& what, const CsvRowVisitor& visit) {
  std::ifstream in(path);
  if (!in) return Error{"", "cannot open " + what + " '" + path.string() + "'"};
  std::vector<std::size_t> index(columns.size());
  std::vector<std::string_view> wanted(columns.size());
  std::size_t field_count = 0;
  std::string line;
  std::size_t line_number = 0;
  bool header_seen = false;
  while (std::getline(in, line)) {
    ++line_number;
    if (trimmed(line).empty()) continue;
    const std::vector<std::string_view> fields = split(line);
    if (!header_seen) {
      for (std::size_t c = 0; c < columns.size(); ++c) {
        const auto it = std::find(fields.begin(), fields.end(), columns[c]);
        if (it == fields.end()) {
          return line_error(line_number, "header lacks column '" + std::string(columns[c]) + "'");
        }
        index[c] = static_cast<std::size_t>(it - fields.begin());
      }
      field_count = fields.size();
      header_seen = true;
      continue;
    }
    if (fields.size() != field_count) {
      return line_error(line_number, "has " + std::to_string(fields.size()) + " fields, the header " +
                                         std::to_string(field_count));
    }
    for (std::size_t c = 0; c < index.size(); ++c) wanted[c] = fields[index[c]];
    if (auto ok = visit(line_number, wanted); !ok) return ok.error();
  }
  if (!header_seen) return Error{"", what + " '" + path.string() + "' is empty"};
  return true;
}

Result<std::vector<CsvRow>> read_csv_columns(const std::filesystem::path& path,
                                             std::span<const std::string_view> columns,
                                             const std::string& what) {
  std::vector<CsvRow> rows;
  auto ok = for_each_csv_row(path, columns, what, [&rows](std::size_t line, std::span<const std::string_view> fields) {
    rows.push_back(CsvRow{line, std::vector<std::string>(fields.begin(), fields.end())});
    return Result<bool>(true);
  });
  if (!ok) return ok.error();
  return rows;
}

}  // namespace visors::core::files
