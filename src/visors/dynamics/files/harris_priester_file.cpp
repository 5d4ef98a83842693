#include "visors/dynamics/files/harris_priester_file.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "visors/core/files/csv_file.hpp"

namespace visors::dynamics::files {

core::Result<HarrisPriesterTable> read_harris_priester_table(const std::filesystem::path& path,
                                                             double f107) {
  const auto level = check_harris_priester_f107(f107);
  if (!level.ok()) return level.error();
  constexpr std::array<std::string_view, 3> kColumns{"altitude_km", "rho_min_kg_per_m3",
                                                     "rho_max_kg_per_m3"};
  const auto rows = core::files::read_csv_columns(path, kColumns, "Harris-Priester table");
  if (!rows.ok()) return rows.error();
  HarrisPriesterTable table;
  table.f107 = f107;
  for (const core::files::CsvRow& row : rows.value()) {
    std::array<double, 3> value{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const auto x = core::files::parse_finite_number(row.fields[c]);
      if (!x) {
        return core::files::line_error(row.line, std::string(kColumns[c]) + ": '" + row.fields[c] + "' is not a number");
      }
      value[c] = *x;
    }
    const double height = value[0] * 1e3;  // [km] -> [m]
    std::optional<double> previous_height;
    if (!table.height_m.empty()) previous_height = table.height_m.back();
    const auto problem = harris_priester_node_problem(height, value[1], value[2], previous_height);
    if (problem) return core::files::line_error(row.line, *problem);
    table.height_m.push_back(height);
    table.rho_min.push_back(value[1]);
    table.rho_max.push_back(value[2]);
  }
  if (table.height_m.size() < 2) {
    return core::Error{"", "Harris-Priester table '" + path.string() + "' needs at least 2 data rows"};
  }
  return table;
}

}  // namespace visors::dynamics::files
