#pragma once
// The content of a run directory (docs/run-directory.md) as the report needs it: timeseries.csv
// column by column, the observations, the events and summary.json. timeseries.csv and
// summary.json are required; a missing or empty observations.csv or events.csv is an empty list,
// because a short run may have neither.

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/report/run_directory.hpp"

namespace visors::report {

/// timeseries.csv by column; all numeric columns have one value per row (NaN when empty).
struct Timeseries {
  std::vector<double> t_s;
  std::vector<std::string> mode;
  std::vector<std::string> active;
  std::vector<double> ada_mean, adl_mean, adex_mean, adey_mean, adix_mean, adiy_mean;
  std::vector<double> ada_osc, adl_osc, adex_osc, adey_osc, adix_osc, adiy_osc;
  std::vector<double> r_r, r_t, r_n;
  std::vector<double> v_r, v_t, v_n;
  std::vector<double> sep_rn, sep_3d, safety_margin;
  std::vector<double> dv_dsc, dv_osc;
  std::vector<double> drag_t_difference, drag_t_estimate;  // [m/s^2] (the estimate NaN while not valid)

  [[nodiscard]] std::size_t size() const { return t_s.size(); }
};

/// One error-budget term at an attempt's worst lateral sample (run_directory.hpp
/// kObservationBudgetColumns) [m].
struct BudgetTermSample {
  double x_m = 0.0, y_m = 0.0, focus_m = 0.0;
};
inline constexpr std::size_t kReportBudgetTerms = kObservationBudgetColumns.size() / 5;

struct Observation {
  double index = 0.0;
  double t_s = 0.0;
  double lateral_error_m = 0.0;
  double lateral_velocity_mps = 0.0;
  double focus_error_m = 0.0;
  bool success = false;
  bool has_budget = false;  // observations.csv has the budget columns, filled (on-board navigation)
  std::array<BudgetTermSample, kReportBudgetTerms> budget{};
};

struct Event {
  double t_s = 0.0;
  std::string spacecraft;
  std::string kind;
  std::string detail;
};

/// navigation.csv (on-board navigation runs) for one spacecraft's filter, by column.
struct NavigationSeries {
  std::vector<double> t_s, fixed_fraction;
  std::vector<double> antenna_r, antenna_t, antenna_n;  // relative antenna position error [m]
  std::vector<double> v_r, v_t, v_n;                    // relative velocity error [m/s]
  std::vector<double> emp_dsc_r, emp_dsc_t, emp_dsc_n, emp_osc_r, emp_osc_t, emp_osc_n;  // [m/s^2]
};

struct RunData {
  std::filesystem::path dir;
  Timeseries timeseries;
  NavigationSeries navigation_dsc, navigation_osc;  // empty without navigation.csv
  std::vector<Observation> observations;
  std::vector<Event> events;
  nlohmann::json summary;  // an object
};

/// Reads the run directory `dir`. Errors name the file (and line and column for a bad cell).
core::Result<RunData> load_run(const std::filesystem::path& dir);

core::Result<Timeseries> load_timeseries(const std::filesystem::path& path);
core::Result<std::vector<Observation>> load_observations(const std::filesystem::path& path);
core::Result<std::vector<Event>> load_events(const std::filesystem::path& path);
core::Result<nlohmann::json> load_summary(const std::filesystem::path& path);
/// navigation.csv split by spacecraft (both empty when the file is absent).
core::Result<bool> load_navigation(const std::filesystem::path& path, NavigationSeries& dsc, NavigationSeries& osc);

}  // namespace visors::report
