// The HTML page of `visors baseline`: one self-contained file (inline SVG, no script) with the
// ENU time series of the baseline by solution status, the IAR figures and the summary tables.
#include <cmath>

#include <fmt/core.h>

#include "apps/baseline/baseline_outputs.hpp"
#include "visors/report/html_text.hpp"
#include "visors/report/svg_plot.hpp"

namespace visors::baseline_app {
namespace {

using baseline::SolutionStatus;
using report::escape_html;

constexpr double kWidth = 1000.0;

struct StatusSeries {
  SolutionStatus status;
  const char* label;
  const char* colour;
};

constexpr StatusSeries kStatusSeries[] = {{SolutionStatus::kFix, "fix", "#1e7d3c"},
                                          {SolutionStatus::kPartial, "partial", "#6a3d9a"},
                                          {SolutionStatus::kFloat, "float", "#d98c00"},
                                          {SolutionStatus::kCode, "code", "#888888"}};

// Minutes since the first epoch.
double minutes(const baseline::BaselineResult& r, const baseline::EpochRecord& e) {
  return e.t.seconds_since(r.epochs.front().t) / 60.0;
}

// Each ENU component minus the reference (the final solution) [cm], one marker series per status.
std::string enu_figure(const baseline::BaselineResult& r, const Eigen::Vector3d& reference) {
  report::Figure figure("fig-enu", kWidth, 230.0, 1);
  const char* names[] = {"east", "north", "up"};
  for (int axis = 0; axis < 3; ++axis) {
    report::Plot plot(fmt::format("{} minus the final solution", names[axis]), "time [min]", "[cm]");
    for (const auto& s : kStatusSeries) {
      std::vector<double> x, y;
      for (const auto& e : r.epochs) {
        if (e.status != s.status) continue;
        x.push_back(minutes(r, e));
        y.push_back(100.0 * (e.solution.baseline_enu_m(axis) - reference(axis)));
      }
      plot.markers(s.label, x, y, report::MarkerShape::kCircle, s.colour);
    }
    figure.add(std::move(plot));
  }
  return figure.svg("Baseline east, north and up minus the final solution, by solution status");
}

std::string iar_figure(const baseline::BaselineResult& r) {
  report::Figure figure("fig-iar", kWidth, 230.0, 2);
  std::vector<double> t, sats, amb, fixed, ratio;
  for (const auto& e : r.epochs) {
    t.push_back(minutes(r, e));
    sats.push_back(e.satellites);
    amb.push_back(static_cast<double>(e.ambiguities));
    fixed.push_back(static_cast<double>(e.fixed));
    ratio.push_back(e.ratio > 0.0 ? std::log10(e.ratio) : NAN);
  }
  report::Plot counts("satellites and ambiguities", "time [min]", "count");
  counts.step("common satellites", t, sats, {"#1f3b73", 1.3, false})
      .step("DD ambiguities", t, amb, {"#d98c00", 1.3, false})
      .step("fixed combinations", t, fixed, {"#1e7d3c", 1.3, true});
  report::Plot ratio_plot("ratio test", "time [min]", "log10(s2 / s1)");
  ratio_plot.line("ratio", t, ratio, {"#1f3b73", 1.3, false}).hline(std::log10(3.0), "threshold 3", {"#b22222", 1.0, true});
  figure.add(std::move(counts));
  figure.add(std::move(ratio_plot));
  return figure.svg("Satellites, ambiguities, fixed combinations and ratio over time");
}

std::string row(const std::string& name, const std::string& value) {
  return fmt::format("<tr><td>{}</td><td>{}</td></tr>\n", escape_html(name), escape_html(value));
}

std::string summary_table(const nlohmann::json& s) {
  std::string html = "<table class=\"summary\">\n";
  html += row("mode", s["settings"].dump());
  html += row("epochs", s["epochs"].dump());
  html += row("statistics", s["statistics"].dump());
  html += row("final fixed", s["solutions"]["final_fixed"].dump());
  html += row("final float", s["solutions"]["final_float"].dump());
  html += row("fixed epochs", s["solutions"]["fixed_epochs"].dump());
  html += row("code-only epochs", s["solutions"]["code_only_epochs"].dump());
  html += row("rejected", s["rejected"].dump());
  return html + "</table>\n";
}

}  // namespace

std::string baseline_page(const BaselineRun& run, const nlohmann::json& summary) {
  const auto& r = run.result;
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>visors baseline</title>\n"
      "<style>body{font-family:sans-serif;margin:1em 2em;max-width:1040px}table{border-collapse:collapse;"
      "font-size:0.85em}td{border:1px solid #ddd;padding:3px 8px;vertical-align:top;word-break:break-all}"
      "svg text{font-size:11px}svg .frame{fill:none;stroke:#888}</style>\n</head>\n<body>\n";
  html += fmt::format("<h1>Baseline {} &rarr; {}</h1>\n", escape_html(run.options.base), escape_html(run.options.rover));
  html += summary_table(summary);
  if (!r.epochs.empty()) {
    const auto& ref = r.final_fixed.valid ? r.final_fixed : r.final_float;
    html += "<h2>Baseline ENU</h2>\n" + enu_figure(r, ref.baseline_enu_m);
    html += "<h2>Ambiguity resolution</h2>\n" + iar_figure(r);
  }
  return html + "</body>\n</html>\n";
}

}  // namespace visors::baseline_app
