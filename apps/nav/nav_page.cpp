// The HTML page of `visors nav`: one self-contained file (inline SVG, no script) with, per filter,
// the figures of the navigation results of Guffanti et al., AAS 23-149, 2023 (sec. 5, Figs. 13-14):
// relative position and velocity errors in
// RTN (the antennas'), the estimated empirical accelerations, the integer-resolution status and
// double differences over time, outages marked; then the summary.
#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/core.h>

#include "apps/nav/nav_replay.hpp"
#include "visors/report/html_text.hpp"
#include "visors/report/svg_plot.hpp"

namespace visors::nav_app {
namespace {

using report::escape_html;

constexpr double kWidth = 1000.0;
constexpr std::size_t kMaxPoints = 3000;  // per series: a day at 1 Hz is decimated to this
constexpr const char* kAxisColours[3] = {"#1f3b73", "#d98c00", "#1e7d3c"};
constexpr const char* kAxisNames[3] = {"R", "T", "N"};

std::size_t stride(const Replay& r) { return std::max<std::size_t>(1, r.epochs.size() / kMaxPoints); }

// The runs of consecutive epochs where `inside(e)` holds, as bands over the panel's y range.
template <typename Inside>
void mark_spans(report::Plot& plot, const Replay& r, double y0, double y1, const char* colour, const char* label,
                Inside inside) {
  bool labelled = false;
  for (std::size_t i = 0; i < r.epochs.size(); ++i) {
    if (!inside(r.epochs[i])) continue;
    std::size_t j = i;
    while (j + 1 < r.epochs.size() && inside(r.epochs[j + 1])) ++j;
    plot.band(r.epochs[i].t_s / 60.0, r.epochs[j].t_s / 60.0, y0, y1, colour, labelled ? "" : label);
    labelled = true;
    i = j;
  }
}

// Outages, slews and observations as bands, the commanded impulses as vertical lines.
void mark_events(report::Plot& plot, const Replay& r, double y0, double y1) {
  mark_spans(plot, r, y0, y1, "#f2d7d5", "GPS outage", [](const EpochScore& e) { return std::string_view(e.status) == "outage"; });
  mark_spans(plot, r, y0, y1, "#e8e8e8", "slew", [](const EpochScore& e) { return e.in_slew; });
  mark_spans(plot, r, y0, y1, "#d5e8f2", "observation", [](const EpochScore& e) { return e.in_observation; });
  std::vector<double> impulses;
  for (double t : r.impulse_t_s) impulses.push_back(t / 60.0);
  if (!impulses.empty()) plot.vlines(impulses, "impulse", {"#7a3e9d", 0.6, true});
}

// One RTN time series per axis of `value(e)` scaled by `scale`, clipped to +-limit.
template <typename Value>
report::Plot rtn_plot(const Replay& r, const std::string& title, const std::string& unit, double scale, double limit,
                      Value value) {
  report::Plot plot(title, "time [min]", unit);
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> t, y;
    for (std::size_t i = 0; i < r.epochs.size(); i += stride(r)) {
      t.push_back(r.epochs[i].t_s / 60.0);
      y.push_back(std::clamp(scale * value(r.epochs[i])(axis), -limit, limit));
    }
    plot.line(kAxisNames[axis], t, y, {kAxisColours[axis], 1.0, false});
  }
  plot.y_range(-limit, limit);
  mark_events(plot, r, -limit, limit);
  return plot;
}

std::string error_figure(const Replay& r) {
  report::Figure figure(fmt::format("fig-rel-{}", r.name), kWidth, 220.0, 1);
  figure.add(rtn_plot(r, "relative position error of the antennas (clipped at 10 mm)", "[mm]", 1e3, 10.0,
                      [](const EpochScore& e) { return e.relative_antenna_rtn_m; }));
  figure.add(rtn_plot(r, "relative velocity error (clipped at 200 um/s)", "[um/s]", 1e6, 200.0,
                      [](const EpochScore& e) { return e.relative_velocity_rtn_mps; }));
  return figure.svg("Relative navigation errors in the DSC's RTN frame");
}

std::string empirical_figure(const Replay& r) {
  report::Figure figure(fmt::format("fig-emp-{}", r.name), kWidth, 200.0, 2);
  figure.add(rtn_plot(r, "DSC empirical acceleration", "[nm/s^2]", 1e9, 3000.0,
                      [](const EpochScore& e) { return e.empirical_dsc_rtn_mps2; }));
  figure.add(rtn_plot(r, "OSC empirical acceleration", "[nm/s^2]", 1e9, 3000.0,
                      [](const EpochScore& e) { return e.empirical_osc_rtn_mps2; }));
  return figure.svg("Estimated empirical accelerations in RTN");
}

std::string iar_figure(const Replay& r) {
  report::Figure figure(fmt::format("fig-iar-{}", r.name), kWidth, 200.0, 2);
  std::vector<double> t, status, dd, wrong;
  for (std::size_t i = 0; i < r.epochs.size(); i += stride(r)) {
    const EpochScore& e = r.epochs[i];
    const std::string_view s(e.status);
    t.push_back(e.t_s / 60.0);
    status.push_back(s == "fixed" ? 3.0 : s == "partial" ? 2.0 : s == "float" ? 1.0 : 0.0);
    dd.push_back(e.double_differences);
  }
  for (const EpochScore& e : r.epochs) {
    if (e.wrong_fix) wrong.push_back(e.t_s / 60.0);
  }
  report::Plot status_plot("integer resolution", "time [min]", "");
  status_plot.step("status", t, status, {"#1f3b73", 1.2, false})
      .y_categories({{0.0, "outage"}, {1.0, "float"}, {2.0, "partial"}, {3.0, "fixed"}})
      .y_range(-0.3, 3.3)
      .left_margin(60.0)
      .vlines(wrong, "wrong fix", {"#b22222", 1.0, false});
  report::Plot dd_plot("double differences", "time [min]", "count");
  dd_plot.step("DD ambiguities", t, dd, {"#1e7d3c", 1.2, false});
  figure.add(std::move(status_plot));
  figure.add(std::move(dd_plot));
  return figure.svg("Ambiguity resolution over time");
}

}  // namespace

std::string nav_page(const std::string& run_dir, const std::vector<Replay>& replays, const nlohmann::json& summary) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>visors nav</title>\n"
      "<style>body{font-family:sans-serif;margin:1em 2em;max-width:1040px}pre{font-size:0.8em;background:#f6f6f6;"
      "padding:0.5em}svg text{font-size:11px}svg .frame{fill:none;stroke:#888}</style>\n</head>\n<body>\n";
  html += fmt::format("<h1>Navigation replay of {}</h1>\n", escape_html(run_dir));
  for (const Replay& r : replays) {
    html += fmt::format("<h2>{} filter</h2>\n", escape_html(r.name));
    if (r.epochs.empty()) continue;
    html += error_figure(r) + empirical_figure(r) + iar_figure(r);
  }
  html += "<h2>Summary</h2>\n<pre>" + escape_html(summary.dump(2)) + "</pre>\n";
  return html + "</body>\n</html>\n";
}

}  // namespace visors::nav_app
