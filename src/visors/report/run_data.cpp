#include "visors/report/run_data.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <utility>

#include "visors/report/csv_table.hpp"
#include "visors/report/run_directory.hpp"

namespace visors::report {
namespace {

// Moves column `name` of `table` into `out`; false (with `error` set) on a bad cell.
bool take_numbers(const CsvTable& table, std::string_view name, std::vector<double>& out,
                  std::optional<core::Error>& error) {
  auto values = table.numbers(name);
  if (!values) {
    error = values.error();
    return false;
  }
  out = std::move(values).value();
  return true;
}

bool take_texts(const CsvTable& table, std::string_view name, std::vector<std::string>& out,
                std::optional<core::Error>& error) {
  auto values = table.texts(name);
  if (!values) {
    error = values.error();
    return false;
  }
  out = std::move(values).value();
  return true;
}

// An optional file that is absent or has no bytes counts as "nothing recorded".
bool absent_or_empty(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) return true;
  return std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) == 0;
}

core::Result<CsvTable> read_table(const std::filesystem::path& path,
                                  std::span<const std::string_view> columns) {
  auto table = CsvTable::read(path);
  if (!table) return table.error();
  if (auto missing = table->require_columns(columns)) return *missing;
  return table;
}

}  // namespace

core::Result<Timeseries> load_timeseries(const std::filesystem::path& path) {
  auto read = read_table(path, kTimeseriesColumns);
  if (!read) return read.error();
  const CsvTable& t = read.value();
  Timeseries s;
  std::optional<core::Error> error;
  // Each column is one strict pass; the && chain stops at the first bad cell.
  const bool ok =
      take_numbers(t, "t_s", s.t_s, error) && take_texts(t, "mode", s.mode, error) &&
      take_texts(t, "active", s.active, error) && take_numbers(t, "ada_mean_m", s.ada_mean, error) &&
      take_numbers(t, "adl_mean_m", s.adl_mean, error) && take_numbers(t, "adex_mean_m", s.adex_mean, error) &&
      take_numbers(t, "adey_mean_m", s.adey_mean, error) && take_numbers(t, "adix_mean_m", s.adix_mean, error) &&
      take_numbers(t, "adiy_mean_m", s.adiy_mean, error) && take_numbers(t, "ada_osc_m", s.ada_osc, error) &&
      take_numbers(t, "adl_osc_m", s.adl_osc, error) && take_numbers(t, "adex_osc_m", s.adex_osc, error) &&
      take_numbers(t, "adey_osc_m", s.adey_osc, error) && take_numbers(t, "adix_osc_m", s.adix_osc, error) &&
      take_numbers(t, "adiy_osc_m", s.adiy_osc, error) && take_numbers(t, "r_r_m", s.r_r, error) &&
      take_numbers(t, "r_t_m", s.r_t, error) && take_numbers(t, "r_n_m", s.r_n, error) &&
      take_numbers(t, "v_r_mps", s.v_r, error) && take_numbers(t, "v_t_mps", s.v_t, error) &&
      take_numbers(t, "v_n_mps", s.v_n, error) && take_numbers(t, "sep_rn_m", s.sep_rn, error) &&
      take_numbers(t, "sep_3d_m", s.sep_3d, error) && take_numbers(t, "safety_margin_m", s.safety_margin, error) &&
      take_numbers(t, "dv_dsc_mps", s.dv_dsc, error) && take_numbers(t, "dv_osc_mps", s.dv_osc, error) &&
      take_numbers(t, "drag_t_difference_mps2", s.drag_t_difference, error) &&
      take_numbers(t, "drag_t_estimate_mps2", s.drag_t_estimate, error);
  if (!ok) return *error;
  // Every sample needs a time: a missing one would misplace all the figures.
  for (std::size_t r = 0; r < s.t_s.size(); ++r) {
    if (!std::isfinite(s.t_s[r])) return t.cell_error(r, "t_s", "is empty");
  }
  return s;
}

// The error budget's position columns (x, y, focus of each term), when observations.csv has them;
// an attempt whose cells are empty (no on-board navigation) has none.
core::Result<bool> load_budget(const CsvTable& t, std::vector<Observation>& observations) {
  if (!t.column(kObservationBudgetColumns[0])) return true;
  for (std::size_t k = 0; k < kReportBudgetTerms; ++k) {
    std::array<std::vector<double>, 3> xyf;
    for (std::size_t c = 0; c < 3; ++c) {
      auto values = t.numbers(kObservationBudgetColumns[5 * k + c]);
      if (!values) return values.error();
      xyf[c] = std::move(values).value();
    }
    for (std::size_t r = 0; r < observations.size(); ++r) {
      observations[r].budget[k] = {xyf[0][r], xyf[1][r], xyf[2][r]};
    }
  }
  for (Observation& o : observations) {
    o.has_budget = std::all_of(o.budget.begin(), o.budget.end(), [](const BudgetTermSample& b) {
      return std::isfinite(b.x_m) && std::isfinite(b.y_m) && std::isfinite(b.focus_m);
    });
  }
  return true;
}

core::Result<std::vector<Observation>> load_observations(const std::filesystem::path& path) {
  if (absent_or_empty(path)) return std::vector<Observation>{};
  auto read = read_table(path, kObservationColumns);
  if (!read) return read.error();
  const CsvTable& t = read.value();
  std::vector<std::vector<double>> columns(kObservationColumns.size());
  for (std::size_t c = 0; c < kObservationColumns.size(); ++c) {
    auto values = t.numbers(kObservationColumns[c]);
    if (!values) return values.error();
    columns[c] = std::move(values).value();
  }
  std::vector<Observation> observations;
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    const double success = columns[5][r];
    if (success != 0.0 && success != 1.0) return t.cell_error(r, "success", "must be 0 or 1");
    Observation o;
    o.index = columns[0][r];
    o.t_s = columns[1][r];
    o.lateral_error_m = columns[2][r];
    o.lateral_velocity_mps = columns[3][r];
    o.focus_error_m = columns[4][r];
    o.success = success == 1.0;
    observations.push_back(o);
  }
  if (auto ok = load_budget(t, observations); !ok) return ok.error();
  return observations;
}

core::Result<std::vector<Event>> load_events(const std::filesystem::path& path) {
  if (absent_or_empty(path)) return std::vector<Event>{};
  auto read = read_table(path, kEventColumns);
  if (!read) return read.error();
  const CsvTable& t = read.value();
  auto times = t.numbers("t_s");
  if (!times) return times.error();
  const std::size_t sc = *t.column("spacecraft");
  const std::size_t kind = *t.column("kind");
  const std::size_t detail = *t.column("detail");
  std::vector<Event> events;
  events.reserve(t.row_count());
  for (std::size_t r = 0; r < t.row_count(); ++r) {
    events.push_back({times.value()[r], t.cell(r, sc), t.cell(r, kind), t.cell(r, detail)});
  }
  return events;
}

core::Result<nlohmann::json> load_summary(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) return core::Error{path.string(), "cannot be opened (missing file?)"};
  nlohmann::json summary = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (summary.is_discarded()) return core::Error{path.string(), "is not valid JSON"};
  if (!summary.is_object()) return core::Error{path.string(), "must hold one JSON object"};
  return summary;
}

core::Result<bool> load_navigation(const std::filesystem::path& path, NavigationSeries& dsc, NavigationSeries& osc) {
  if (absent_or_empty(path)) return true;
  auto read = read_table(path, kNavigationColumns);
  if (!read) return read.error();
  const CsvTable& t = read.value();
  const std::size_t craft = *t.column("spacecraft");
  const std::array<std::pair<std::string_view, std::vector<double> NavigationSeries::*>, 14> columns{{
      {"t_s", &NavigationSeries::t_s},
      {"fixed_fraction", &NavigationSeries::fixed_fraction},
      {"antenna_r_m", &NavigationSeries::antenna_r},
      {"antenna_t_m", &NavigationSeries::antenna_t},
      {"antenna_n_m", &NavigationSeries::antenna_n},
      {"rel_vr_mps", &NavigationSeries::v_r},
      {"rel_vt_mps", &NavigationSeries::v_t},
      {"rel_vn_mps", &NavigationSeries::v_n},
      {"emp_dsc_r_mps2", &NavigationSeries::emp_dsc_r},
      {"emp_dsc_t_mps2", &NavigationSeries::emp_dsc_t},
      {"emp_dsc_n_mps2", &NavigationSeries::emp_dsc_n},
      {"emp_osc_r_mps2", &NavigationSeries::emp_osc_r},
      {"emp_osc_t_mps2", &NavigationSeries::emp_osc_t},
      {"emp_osc_n_mps2", &NavigationSeries::emp_osc_n},
  }};
  for (const auto& [name, member] : columns) {
    auto values = t.numbers(name);
    if (!values) return values.error();
    for (std::size_t r = 0; r < t.row_count(); ++r) {
      const std::string& who = t.cell(r, craft);
      if (who != "dsc" && who != "osc") return t.cell_error(r, "spacecraft", "must be dsc or osc");
      ((who == "dsc" ? dsc : osc).*member).push_back(values.value()[r]);
    }
  }
  return true;
}

core::Result<RunData> load_run(const std::filesystem::path& dir) {
  RunData run;
  run.dir = dir;
  auto summary = load_summary(dir / kSummaryFile);
  if (!summary) return summary.error();
  run.summary = std::move(summary).value();
  auto timeseries = load_timeseries(dir / kTimeseriesFile);
  if (!timeseries) return timeseries.error();
  run.timeseries = std::move(timeseries).value();
  auto observations = load_observations(dir / kObservationsFile);
  if (!observations) return observations.error();
  run.observations = std::move(observations).value();
  auto events = load_events(dir / kEventsFile);
  if (!events) return events.error();
  run.events = std::move(events).value();
  if (auto ok = load_navigation(dir / kNavigationFile, run.navigation_dsc, run.navigation_osc); !ok) return ok.error();
  return run;
}

}  // namespace visors::report
