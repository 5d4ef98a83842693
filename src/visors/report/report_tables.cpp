#include "visors/report/report_tables.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include <fmt/core.h>

#include "visors/report/html_text.hpp"
#include "visors/report/summary_fields.hpp"

namespace visors::report {
namespace {

constexpr const char* kModeRows[] = {"manual", "standby", "transfer_to_science", "science", "transfer_to_standby",
                                     "escape", "total"};
constexpr double kSecondsPerWeek = 7.0 * 86400.0;

std::string none(const char* id, const char* heading) {
  return fmt::format("<section id=\"{}\"><h2>{}</h2><p class=\"none\">none</p></section>\n", id, heading);
}

// A <tr> of cells already escaped.
std::string row(std::initializer_list<std::string> cells, const char* tag = "td") {
  std::string out = "<tr>";
  for (const std::string& c : cells) out += fmt::format("<{0}>{1}</{0}>", tag, c);
  return out + "</tr>\n";
}

std::string cell_class(bool ok) { return ok ? "pass" : "fail"; }

// A table cell that turns red when `value` exceeds `limit` (a missing limit judges nothing).
std::string judged_cell(double value, double limit, double factor, int decimals) {
  const bool bad = std::isfinite(limit) && !(value <= limit);
  return fmt::format("<td class=\"{}\">{}</td>", bad ? "fail" : "", format_fixed(value * factor, decimals));
}

// Number of stretches of the timeseries in `mode` (each transfer is one stretch).
std::size_t stretches_in(const Timeseries& ts, const std::string& mode) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    if (ts.mode[i] == mode && (i == 0 || ts.mode[i - 1] != mode)) ++n;
  }
  return n;
}

// Seconds the timeseries spends in `mode` (each sample holds until the next).
double seconds_in(const Timeseries& ts, const std::string& mode) {
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    if (ts.mode[i] == mode) total += ts.t_s[i + 1] - ts.t_s[i];
  }
  return total;
}

std::string text_or_dash(const std::string& text) { return text.empty() ? "\u2013" : escape_html(text); }

}  // namespace

std::string summary_box(const RunData& run) {
  const nlohmann::json& s = run.summary;
  const double simulated = summary_number(s, {"simulated_s"});
  const double wall = summary_number(s, {"wall_s"});
  double rate = summary_number(s, {"success_rate"});  // a fraction in [0, 1]
  if (std::isnan(rate) && !run.observations.empty()) {  // an older summary: count them here
    const auto successes = std::count_if(run.observations.begin(), run.observations.end(),
                                         [](const Observation& o) { return o.success; });
    rate = static_cast<double>(successes) / static_cast<double>(run.observations.size());
  }
  const double epsilon = summary_number(s, {"requirements", "safety_epsilon_m"});
  const double min_rn = summary_number(s, {"min_separation_rn_m"});
  const double min_3d = summary_number(s, {"min_separation_3d_m"});
  const double violations = summary_number(s, {"safety_violations"});
  std::string out = "<section id=\"summary\"><h2>Summary</h2>\n<table class=\"summary\">\n";
  out += row({"scenario", text_or_dash(summary_text(s, {"scenario"}))});
  out += row({"t0", text_or_dash(summary_text(s, {"t0", "iso"})) + " (GPS week " +
                        text_or_dash(summary_text(s, {"t0", "week"})) + ", " +
                        text_or_dash(summary_text(s, {"t0", "seconds_of_week"})) + " s)"});
  out += row({"seed", text_or_dash(summary_text(s, {"seed"}))});
  out += row({"simulated time", format_fixed(simulated / 3600.0, 2) + " h (" + format_fixed(simulated, 0) + " s)"});
  out += row({"wall time", format_fixed(wall, 2) + " s"});
  out += row({"speed-up", format_fixed(simulated / wall, 0) + " \u00d7 real time"});
  out += row({"observations", std::to_string(run.observations.size())});
  out += fmt::format("<tr><td>success rate</td><td class=\"{}\">{} % (requirement \u2265 {} %)</td></tr>\n",
                     cell_class(rate >= kRequiredSuccessRate), format_fixed(100.0 * rate, 1),
                     format_fixed(100.0 * kRequiredSuccessRate, 0));
  out += fmt::format("<tr><td>minimum RN separation</td><td class=\"{}\">{} m (\u03b5 = {} m)</td></tr>\n",
                     cell_class(!(min_rn < epsilon)), format_fixed(min_rn, 2), format_fixed(epsilon, 2));
  out += row({"minimum 3D separation", format_fixed(min_3d, 2) + " m"});
  out += fmt::format("<tr><td>safety violations</td><td class=\"{}\">{}</td></tr>\n", cell_class(violations == 0.0),
                     format_fixed(violations, 0));
  out += row({"final mode", text_or_dash(summary_text(s, {"final_mode"}))});
  return out + "</table></section>\n";
}

std::string delta_v_table(const RunData& run) {
  const nlohmann::json& s = run.summary;
  const double standby_weeks = seconds_in(run.timeseries, "standby") / kSecondsPerWeek;
  const double observations = static_cast<double>(run.observations.size());
  const auto paper = [&s](const char* key) { return summary_number(s, {"paper_budget_mps", key}); };
  const auto count = [&run](const char* mode) {
    return static_cast<double>(stretches_in(run.timeseries, mode));
  };
  // The paper gives rates (per week, per observation) or costs per transfer; scaled to this run
  // they are comparable with the executed delta-v of the same mode.
  struct PaperEntry {
    const char* mode;
    std::string figure;
    double scaled;
  };
  const PaperEntry entries[] = {
      {"standby", format_fixed(paper("standby_per_week"), 4) + " m/s per week", paper("standby_per_week") * standby_weeks},
      {"transfer_to_science", format_fixed(paper("transfer_to_science"), 4) + " m/s per transfer",
       paper("transfer_to_science") * count("transfer_to_science")},
      {"transfer_to_standby", format_fixed(paper("transfer_to_standby"), 4) + " m/s per transfer",
       paper("transfer_to_standby") * count("transfer_to_standby")},
      {"science", format_fixed(paper("science_per_observation"), 4) + " m/s per observation",
       paper("science_per_observation") * observations},
  };
  std::string out =
      "<section id=\"delta-v-budget\"><h2>Delta-v budget</h2>\n<table>\n"
      "<tr><th>mode</th><th>DSC [m/s]</th><th>OSC [m/s]</th><th>formation [m/s]</th>"
      "<th>paper budget</th><th>paper, scaled to this run [m/s]</th></tr>\n";
  for (const char* mode : kModeRows) {
    const double dsc = summary_number(s, {"delta_v_mps", "dsc", mode});
    const double osc = summary_number(s, {"delta_v_mps", "osc", mode});
    std::string figure = "\u2013";
    std::string scaled = "\u2013";
    for (const PaperEntry& e : entries) {
      if (std::string_view(e.mode) == mode) {
        figure = escape_html(e.figure);
        scaled = format_fixed(e.scaled, 4);
      }
    }
    out += row({escape_html(mode), format_fixed(dsc, 4), format_fixed(osc, 4), format_fixed(dsc + osc, 4), figure,
                scaled});
  }
  return out +
         "</table>\n<p class=\"note\">Executed delta-v by the mode the spacecraft was in when it fired. Paper "
         "budget: Guffanti et al. 2023; scaled by the weeks spent in standby, the number of transfers seen in "
         "the time series and the number of observations.</p></section>\n";
}

std::string observation_table(const RunData& run) {
  if (run.observations.empty()) return none("observations", "Observations");
  const nlohmann::json& s = run.summary;
  const double lateral = summary_number(s, {"requirements", "lateral_error_m"});
  const double velocity = summary_number(s, {"requirements", "lateral_velocity_mps"});
  const double focus = summary_number(s, {"requirements", "focus_error_m"});
  std::string out =
      "<section id=\"observations\"><h2>Observations</h2>\n<table>\n"
      "<tr><th>#</th><th>start [s]</th><th>start [h]</th><th>lateral error [mm]</th>"
      "<th>lateral velocity [mm/s]</th><th>focus error [mm]</th><th>result</th></tr>\n";
  out += fmt::format("<tr class=\"requirement\"><td colspan=\"3\">requirement</td><td>\u2264 {}</td>"
                     "<td>\u2264 {}</td><td>\u2264 {}</td><td></td></tr>\n",
                     format_fixed(1e3 * lateral, 1), format_fixed(1e3 * velocity, 2), format_fixed(1e3 * focus, 1));
  for (const Observation& o : run.observations) {
    out += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td>{}{}{}<td class=\"{}\">{}</td></tr>\n",
                       format_fixed(o.index, 0), format_fixed(o.t_s, 1), format_fixed(o.t_s / 3600.0, 3),
                       judged_cell(o.lateral_error_m, lateral, 1e3, 2),
                       judged_cell(o.lateral_velocity_mps, velocity, 1e3, 3), judged_cell(o.focus_error_m, focus, 1e3, 2),
                       cell_class(o.success), o.success ? "success" : "failure");
  }
  return out + "</table></section>\n";
}

std::string budget_table(const RunData& run) {
  const auto with_budget = [](const Observation& o) { return o.has_budget; };
  if (std::none_of(run.observations.begin(), run.observations.end(), with_budget)) {
    return none("error-budget", "Error budget");
  }
  std::string out =
      "<section id=\"error-budget\"><h2>Error budget</h2>\n<p>Each attempt's true alignment error at its worst "
      "lateral sample, split by source (the terms add up to it): lateral x, y and focus [mm].</p>\n<table>\n"
      "<tr><th>#</th><th>lateral error [mm]</th>";
  for (std::size_t k = 0; k < kReportBudgetTerms; ++k) {
    std::string_view name = kObservationBudgetColumns[5 * k];  // budget_<term>_x_m
    name.remove_prefix(std::string_view("budget_").size());
    name.remove_suffix(std::string_view("_x_m").size());
    std::string label(name);
    std::replace(label.begin(), label.end(), '_', ' ');
    out += fmt::format("<th>{}</th>", label);
  }
  out += "</tr>\n";
  for (const Observation& o : run.observations) {
    if (!o.has_budget) continue;
    out += fmt::format("<tr><td>{}</td><td>{}</td>", format_fixed(o.index, 0), format_fixed(1e3 * o.lateral_error_m, 1));
    for (const BudgetTermSample& b : o.budget) {
      out += fmt::format("<td>{}, {}, {}</td>", format_fixed(1e3 * b.x_m, 1), format_fixed(1e3 * b.y_m, 1),
                         format_fixed(1e3 * b.focus_m, 1));
    }
    out += "</tr>\n";
  }
  return out + "</table></section>\n";
}

std::string event_table(const RunData& run) {
  if (run.events.empty()) return none("events", "Event log");
  std::string out =
      "<section id=\"events\"><h2>Event log</h2>\n<table>\n"
      "<tr><th>t [s]</th><th>t [h]</th><th>spacecraft</th><th>kind</th><th>detail</th></tr>\n";
  const std::size_t shown = std::min(run.events.size(), kMaxEventsListed);
  for (std::size_t i = 0; i < shown; ++i) {
    const Event& e = run.events[i];
    out += row({format_fixed(e.t_s, 1), format_fixed(e.t_s / 3600.0, 3), escape_html(e.spacecraft),
                escape_html(e.kind), escape_html(e.detail)});
  }
  out += "</table>\n";
  if (run.events.size() > shown) {
    out += fmt::format("<p class=\"note\">\u2026 and {} more events not listed (events.csv has all {}).</p>\n",
                       run.events.size() - shown, run.events.size());
  }
  return out + "</section>\n";
}

}  // namespace visors::report
