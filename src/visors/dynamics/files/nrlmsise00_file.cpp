#include "visors/dynamics/files/nrlmsise00_file.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "visors/core/files/csv_file.hpp"
#include "visors/core/files/text_file.hpp"

namespace visors::dynamics::files {
namespace {

using core::Error;
using core::files::line_error;

// One table of the file: its name, its size and where each of its rows goes.
struct TableSpec {
  std::string_view name;
  std::size_t rows = 0;
  std::size_t columns = 0;
  std::array<double*, 10> row{};  // the largest table (pma) has 10 rows
};

template <std::size_t N>
TableSpec spec(std::string_view name, std::array<double, N>& a) {
  TableSpec s{name, 1, N, {}};
  s.row[0] = a.data();
  return s;
}

template <std::size_t R, std::size_t N>
TableSpec spec(std::string_view name, std::array<std::array<double, N>, R>& a) {
  static_assert(R <= 10);
  TableSpec s{name, R, N, {}};
  for (std::size_t r = 0; r < R; ++r) s.row[r] = a[r].data();
  return s;
}

std::array<TableSpec, 10> table_specs(Nrlmsise00Coefficients& c) {
  return {spec("pt", c.pt),   spec("pd", c.pd),   spec("ps", c.ps),   spec("pdl", c.pdl), spec("ptm", c.ptm),
          spec("pdm", c.pdm), spec("ptl", c.ptl), spec("pma", c.pma), spec("sam", c.sam), spec("pavgm", c.pavgm)};
}

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string_view> tokens(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const auto start = s.find_first_not_of(" \t\r", i);
    if (start == std::string_view::npos) break;
    auto end = s.find_first_of(" \t\r", start);
    if (end == std::string_view::npos) end = s.size();
    out.push_back(s.substr(start, end - start));
    i = end;
  }
  return out;
}

std::optional<std::size_t> parse_count(std::string_view text) {
  if (text.empty() || text.size() > 6) return std::nullopt;
  std::size_t n = 0;
  for (const char ch : text) {
    if (ch < '0' || ch > '9') return std::nullopt;
    n = n * 10 + static_cast<std::size_t>(ch - '0');
  }
  return n;
}

std::string names_list(std::span<const TableSpec> specs) {
  std::string s;
  for (const TableSpec& t : specs) {
    if (!s.empty()) s += ", ";
    s += t.name;
  }
  return s;
}

// The reading state: the table being filled and how many of its rows were read.
struct Reader {
  std::array<TableSpec, 10> specs;
  std::array<std::size_t, 10> header_line{};  // 0: not seen
  std::optional<std::size_t> current;
  std::size_t rows_read = 0;

  std::optional<Error> header(std::size_t line, std::span<const std::string_view> t);
  std::optional<Error> row(std::size_t line, std::span<const std::string_view> t);
  [[nodiscard]] std::string where() const {
    return "table " + std::string(specs[*current].name) + " row " + std::to_string(rows_read);
  }
};

std::optional<Error> Reader::header(std::size_t line, std::span<const std::string_view> t) {
  if (current) {
    return line_error(line, "table " + std::string(specs[*current].name) + " has " + std::to_string(rows_read) +
                                " of its " + std::to_string(specs[*current].rows) + " rows before this header");
  }
  if (t.size() != 4) return line_error(line, "table header must read 'array NAME ROWS COLS'");
  std::size_t k = 0;
  while (k < specs.size() && specs[k].name != t[1]) ++k;
  if (k == specs.size()) {
    return line_error(line, "unknown table '" + std::string(t[1]) + "' (NRLMSISE-00 has " + names_list(specs) + ")");
  }
  const TableSpec& s = specs[k];
  if (header_line[k] != 0) {
    return line_error(line, "table " + std::string(s.name) + " appears twice (first at line " +
                                std::to_string(header_line[k]) + ")");
  }
  const auto rows = parse_count(t[2]);
  const auto columns = parse_count(t[3]);
  if (!rows || !columns || *rows != s.rows || *columns != s.columns) {
    return line_error(line, "table " + std::string(s.name) + " must be " + std::to_string(s.rows) + " x " +
                                std::to_string(s.columns) + ", the header says " + std::string(t[2]) + " x " +
                                std::string(t[3]));
  }
  header_line[k] = line;
  current = k;
  rows_read = 0;
  return std::nullopt;
}

std::optional<Error> Reader::row(std::size_t line, std::span<const std::string_view> t) {
  if (!current) return line_error(line, "numbers outside a table (expected 'array NAME ROWS COLS')");
  const TableSpec& s = specs[*current];
  if (t.size() != s.columns) {
    return line_error(line, where() + ": " + std::to_string(t.size()) + " numbers, expected " +
                                std::to_string(s.columns));
  }
  for (std::size_t col = 0; col < t.size(); ++col) {
    const auto value = core::files::parse_finite_number(t[col]);
    if (!value) {
      return line_error(line, where() + " column " + std::to_string(col) + ": '" + std::string(t[col]) +
                                  "' is not a finite number");
    }
    s.row[rows_read][col] = *value;
  }
  if (++rows_read == s.rows) current.reset();
  return std::nullopt;
}

}  // namespace

core::Result<Nrlmsise00Coefficients> parse_nrlmsise00_coefficients(std::string_view text, std::string_view source) {
  Nrlmsise00Coefficients c;
  Reader reader{table_specs(c), {}, std::nullopt, 0};
  std::size_t line = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    auto end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view content = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line;
    if (content.empty() || content.front() == '#') continue;
    const std::vector<std::string_view> t = tokens(content);
    const auto problem = t.front() == "array" ? reader.header(line, t) : reader.row(line, t);
    if (problem) return *problem;
  }
  if (reader.current) {
    const TableSpec& s = reader.specs[*reader.current];
    std::string message = "the file '";
    message += source;
    message += "' ends after " + std::to_string(reader.rows_read) + " of the table's " + std::to_string(s.rows) + " rows";
    return Error{std::string(s.name), message};
  }
  for (std::size_t k = 0; k < reader.specs.size(); ++k) {
    if (reader.header_line[k] == 0) {
      std::string message = "table missing from '";
      message += source;
      message += "'";
      return Error{std::string(reader.specs[k].name), message};
    }
  }
  if (auto problem = nrlmsise00_coefficients_problem(c)) return *problem;
  return c;
}

core::Result<Nrlmsise00Coefficients> read_nrlmsise00_coefficients(const std::filesystem::path& path) {
  const auto text = core::files::read_text_file(path);
  if (!text) return Error{"", "cannot open NRLMSISE-00 coefficient file '" + path.string() + "'"};
  return parse_nrlmsise00_coefficients(*text, path.string());
}

}  // namespace visors::dynamics::files
