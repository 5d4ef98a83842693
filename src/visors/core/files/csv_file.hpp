#pragma once
// Reading tables in CSV with a header line (Harris-Priester densities, CelesTrak space weather,
// the simulator's truth files): the wanted columns are found by header name, so column order and
// extra columns do not matter; blank lines are skipped; fields are trimmed of blanks. Ground-side
// file I/O (visors_core_files). Small tables are read whole (read_csv_columns); large ones (a
// day's channels_truth.csv is 240 MB: held as strings, 380 MB more) row by row (for_each_csv_row).

#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "visors/core/result.hpp"

namespace visors::core::files {

struct CsvRow {
  std::size_t line = 0;             // 1-based line number in the file
  std::vector<std::string> fields;  // the wanted columns, in the order they were asked for
};

/// All data rows of `path`, keeping the `columns` named in the header. `what` names the file's
/// content in messages ("space-weather file"). Errors: the file cannot be opened or is empty, a
/// column is missing ("line 1"), a row has a different number of fields than the header
/// ("line N").
Result<std::vector<CsvRow>> read_csv_columns(const std::filesystem::path& path,
                                             std::span<const std::string_view> columns,
                                             const std::string& what);

/// Called with each data row's line number and its wanted fields (in the order asked for; the
/// views live until the call returns); an error stops the reading and is returned.
using CsvRowVisitor = std::function<Result<bool>(std::size_t line, std::span<const std::string_view> fields)>;

/// The rows of `path` one at a time, as read_csv_columns, without holding the file.
Result<bool> for_each_csv_row(const std::filesystem::path& path, std::span<const std::string_view> columns,
                              const std::string& what, const CsvRowVisitor& visit);

/// A finite decimal number filling the whole field; nullopt otherwise (empty, trailing text, inf).
std::optional<double> parse_finite_number(std::string_view text);

/// The error for line `line` of a file: field "line N".
Error line_error(std::size_t line, std::string message);

}  // namespace visors::core::files
