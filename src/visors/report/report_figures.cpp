#include "visors/report/report_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/core.h>

#include "visors/report/html_text.hpp"
#include "visors/report/summary_fields.hpp"
#include "visors/report/svg_plot.hpp"

namespace visors::report {
namespace {

constexpr double kWidth = 960.0;
const Style kMean{"#1b2a49", 1.4, false};
const Style kOsculating{"#bdbdbd", 1.0, false};
const Style kTrajectory{"#1b2a49", 0.9, false};
const Style kObservationMark{"#7cc4b8", 1.0, false};
const Style kModeMark{"#e9967a", 1.0, true};
const Style kRequirement{"#c0392b", 1.3, true};
constexpr const char* kSuccessColour = "#2e8b57";
constexpr const char* kFailureColour = "#c0392b";

// The modes of docs/run-directory.md, bottom to top on the timeline.
constexpr std::array<const char*, 6> kModes{"manual", "standby", "transfer_to_science", "science",
                                            "transfer_to_standby", "escape"};
constexpr std::array<const char*, 6> kModeColours{"#9e9e9e", "#8ab6d6", "#f4c06f", "#6fbf73", "#f29e6d", "#d9534f"};

std::string wrap(const std::string& id, const std::string& svg, const std::string& caption) {
  return fmt::format("<figure id=\"{}-figure\">\n{}<figcaption>{}</figcaption>\n</figure>\n", id, svg,
                     escape_html(caption));
}

std::vector<double> hours(const std::vector<double>& seconds) {
  std::vector<double> h(seconds.size());
  std::transform(seconds.begin(), seconds.end(), h.begin(), [](double s) { return s / 3600.0; });
  return h;
}

// Times (h) where the mode column changes value.
std::vector<double> mode_change_hours(const Timeseries& ts) {
  std::vector<double> t;
  for (std::size_t i = 1; i < ts.size(); ++i) {
    if (ts.mode[i] != ts.mode[i - 1]) t.push_back(ts.t_s[i] / 3600.0);
  }
  return t;
}

std::vector<double> observation_hours(const RunData& run) {
  std::vector<double> t;
  for (const Observation& o : run.observations) t.push_back(o.t_s / 3600.0);
  return t;
}

// Observation starts and mode changes as vertical lines on a time panel.
void add_time_marks(Plot& plot, const RunData& run) {
  plot.vlines(observation_hours(run), "observation", kObservationMark);
  plot.vlines(mode_change_hours(run.timeseries), "mode change", kModeMark);
}

bool any_finite(const std::vector<double>& v) {
  return std::any_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}

// First and last sample of a planar curve, so the direction of travel can be read.
void add_ends(Plot& plot, const std::vector<double>& x, const std::vector<double>& y) {
  if (x.empty()) return;
  plot.markers("start", std::vector<double>{x.front()}, std::vector<double>{y.front()}, MarkerShape::kCircle,
               kSuccessColour);
  plot.markers("end", std::vector<double>{x.back()}, std::vector<double>{y.back()}, MarkerShape::kCross,
               kFailureColour);
}

}  // namespace

std::string roe_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  const std::vector<double> t = hours(ts.t_s);
  struct Panel {
    const char* title;
    const std::vector<double>* mean;
    const std::vector<double>* osc;
  };
  const Panel panels[] = {{"a\u03b4a", &ts.ada_mean, &ts.ada_osc},    {"a\u03b4\u03bb", &ts.adl_mean, &ts.adl_osc},
                          {"a\u03b4e_x", &ts.adex_mean, &ts.adex_osc}, {"a\u03b4e_y", &ts.adey_mean, &ts.adey_osc},
                          {"a\u03b4i_x", &ts.adix_mean, &ts.adix_osc}, {"a\u03b4i_y", &ts.adiy_mean, &ts.adiy_osc}};
  Figure figure("fig-roe-mean-osc", kWidth, 230.0, 2);
  for (const Panel& p : panels) {
    Plot& plot = figure.add(Plot(p.title, "time [h]", "[m]"));
    plot.line("osculating", t, *p.osc, kOsculating).line("mean", t, *p.mean, kMean);
    add_time_marks(plot, run);
  }
  return wrap("fig-roe-mean-osc", figure.svg("relative orbital elements, mean and osculating, versus time"),
              "Relative orbital elements scaled by the chief's semi-major axis: mean (dark) and osculating "
              "(light grey), truth, versus time since t0. Vertical lines: observation starts and mode changes.");
}

std::string ei_vector_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  Figure figure("fig-ei-vectors", kWidth, 400.0, 2);
  // One vector plane: osculating and mean curves, start and end marks, equal scales.
  const auto plane = [&](const char* title, const char* x_label, const char* y_label, const std::vector<double>& x_osc,
                         const std::vector<double>& y_osc, const std::vector<double>& x_mean,
                         const std::vector<double>& y_mean) {
    Plot& plot = figure.add(Plot(title, x_label, y_label));
    plot.curve("osculating", x_osc, y_osc, kOsculating).curve("mean", x_mean, y_mean, kMean);
    add_ends(plot, x_mean, y_mean);
    plot.equal_aspect();
  };
  plane("relative eccentricity vector", "a\u03b4e_x [m]", "a\u03b4e_y [m]", ts.adex_osc, ts.adey_osc, ts.adex_mean,
        ts.adey_mean);
  plane("relative inclination vector", "a\u03b4i_x [m]", "a\u03b4i_y [m]", ts.adix_osc, ts.adiy_osc, ts.adix_mean,
        ts.adiy_mean);
  return wrap("fig-ei-vectors", figure.svg("relative eccentricity and inclination vector planes"),
              "Relative e-vector (a\u03b4e_x, a\u03b4e_y) and i-vector (a\u03b4i_x, a\u03b4i_y) planes, mean "
              "(dark) and osculating (light grey), equal scales; circle: start, cross: end.");
}

std::string separation_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  const std::vector<double> t = hours(ts.t_s);
  const double epsilon = summary_number(run.summary, {"requirements", "safety_epsilon_m"});
  Figure figure("fig-separation", kWidth, 320.0, 1);
  Plot& plot = figure.add(Plot("separation", "time [h]", "[m]"));
  plot.line("3D separation", t, ts.sep_3d, Style{"#e07b39", 1.2, false})
      .line("RN separation", t, ts.sep_rn, kMean);
  if (any_finite(ts.safety_margin)) {
    plot.line("on-board safety margin", t, ts.safety_margin, Style{"#2e8b57", 1.2, false});
  }
  plot.hline(epsilon, fmt::format("safety \u03b5 = {} m", format_fixed(epsilon, 2)), kRequirement);
  add_time_marks(plot, run);
  return wrap("fig-separation", figure.svg("separation versus time with the safety threshold"),
              "Separation of the two spacecraft in the radial-normal plane and in 3D (truth), the active "
              "spacecraft's on-board passive-safety margin when recorded, and the safety threshold \u03b5.");
}

std::string trajectory_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  Figure figure("fig-trajectory-rtn", kWidth, 400.0, 2);
  Plot& rt = figure.add(Plot("RT projection", "T [m]", "R [m]"));
  rt.curve("trajectory", ts.r_t, ts.r_r, kTrajectory);
  add_ends(rt, ts.r_t, ts.r_r);
  rt.equal_aspect();
  Plot& rn = figure.add(Plot("RN projection", "N [m]", "R [m]"));
  rn.curve("trajectory", ts.r_n, ts.r_r, kTrajectory);
  add_ends(rn, ts.r_n, ts.r_r);
  rn.equal_aspect();
  return wrap("fig-trajectory-rtn", figure.svg("relative trajectory in the RTN frame"),
              "Relative position of the OSC in the DSC's RTN frame (truth), equal scales; circle: start, "
              "cross: end.");
}

std::string alignment_figure(const RunData& run) {
  struct Metric {
    const char* title;
    const char* unit;
    double Observation::*member;
    const char* requirement_key;
  };
  const Metric metrics[] = {{"lateral error", "[mm]", &Observation::lateral_error_m, "lateral_error_m"},
                            {"lateral velocity", "[mm/s]", &Observation::lateral_velocity_mps, "lateral_velocity_mps"},
                            {"focus error", "[mm]", &Observation::focus_error_m, "focus_error_m"}};
  Figure figure("fig-alignment", kWidth, 300.0, 3);
  for (const Metric& m : metrics) {
    std::vector<double> ok_x, ok_y, bad_x, bad_y;
    for (const Observation& o : run.observations) {
      (o.success ? ok_x : bad_x).push_back(o.index);
      (o.success ? ok_y : bad_y).push_back(1e3 * (o.*m.member));  // metres -> millimetres
    }
    const double requirement = 1e3 * summary_number(run.summary, {"requirements", m.requirement_key});
    Plot& plot = figure.add(Plot(m.title, "observation", m.unit));
    plot.markers("success", ok_x, ok_y, MarkerShape::kCircle, kSuccessColour)
        .markers("failure", bad_x, bad_y, MarkerShape::kCross, kFailureColour)
        .hline(requirement, "requirement", kRequirement);
  }
  return wrap("fig-alignment", figure.svg("alignment metrics per observation with requirements"),
              "Worst value over each 10 s observation window of the lateral error, lateral velocity and focus "
              "error; circles: successful observations, crosses: failed ones; dashed: the requirement.");
}

std::string delta_v_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  const std::vector<double> t = hours(ts.t_s);
  Figure figure("fig-delta-v", kWidth, 300.0, 1);
  Plot& plot = figure.add(Plot("cumulative delta-v", "time [h]", "[m/s]"));
  plot.line("DSC", t, ts.dv_dsc, kMean).line("OSC", t, ts.dv_osc, Style{"#e07b39", 1.4, false});
  plot.vlines(mode_change_hours(ts), "mode change", kModeMark);
  return wrap("fig-delta-v", figure.svg("cumulative delta-v of both spacecraft versus time"),
              "Cumulative executed delta-v of each spacecraft (L1 norm in the thrusters' frame).");
}

std::string drag_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  const std::vector<double> t = hours(ts.t_s);
  const auto micro = [](const std::vector<double>& v) {
    std::vector<double> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [](double x) { return 1e6 * x; });
    return out;
  };
  Figure figure("fig-drag", kWidth, 300.0, 1);
  Plot& plot = figure.add(Plot("differential drag, along-track", "time [h]", "[\u00b5m/s\u00b2]"));
  plot.line("truth (OSC minus DSC)", t, micro(ts.drag_t_difference), kMean);
  if (any_finite(ts.drag_t_estimate)) {
    plot.line("on-board estimate (active)", t, micro(ts.drag_t_estimate), Style{"#e07b39", 1.2, false});
  }
  add_time_marks(plot, run);
  return wrap("fig-drag", figure.svg("differential along-track drag, truth and on-board estimate, versus time"),
              "The true drag acceleration of the OSC minus the DSC's along the DSC's T axis (attitude-dependent "
              "areas, the truth's atmosphere) and the active spacecraft's on-board estimate, which its planners "
              "aim off by (docs/drag-prediction.md).");
}

std::string mode_figure(const RunData& run) {
  const Timeseries& ts = run.timeseries;
  std::vector<std::string> names(kModes.begin(), kModes.end());
  for (const std::string& m : ts.mode) {  // modes outside the documented list get their own rows
    if (std::find(names.begin(), names.end(), m) == names.end()) names.push_back(m);
  }
  const auto level = [&names](const std::string& m) {
    return static_cast<double>(std::find(names.begin(), names.end(), m) - names.begin());
  };
  Figure figure("fig-modes", kWidth, 280.0, 1);
  Plot& plot = figure.add(Plot("mode of the active spacecraft", "time [h]", ""));
  std::vector<double> t = hours(ts.t_s);
  std::vector<double> y;
  for (const std::string& m : ts.mode) y.push_back(level(m));
  // One band per run of equal mode, from its first sample to the next run's first sample.
  for (std::size_t begin = 0; begin < ts.size();) {
    std::size_t end = begin + 1;
    while (end < ts.size() && ts.mode[end] == ts.mode[begin]) ++end;
    const double lv = level(ts.mode[begin]);
    const std::size_t index = static_cast<std::size_t>(lv);
    const char* colour = index < kModeColours.size() ? kModeColours[index] : "#b39ddb";
    plot.band(t[begin], t[std::min(end, ts.size() - 1)], lv - 0.35, lv + 0.35, colour, ts.mode[begin]);
    begin = end;
  }
  plot.step("", t, y, Style{"#333333", 1.0, false});
  std::vector<std::pair<double, std::string>> ticks;
  for (std::size_t i = 0; i < names.size(); ++i) ticks.emplace_back(static_cast<double>(i), names[i]);
  plot.y_categories(ticks).left_margin(140.0).y_range(-0.6, static_cast<double>(names.size()) - 0.4);
  return wrap("fig-modes", figure.svg("mode timeline"),
              "Mode of the active spacecraft versus time (one coloured band per stretch in a mode).");
}

std::string navigation_figure(const RunData& run) {
  if (run.navigation_osc.t_s.empty() && run.navigation_dsc.t_s.empty()) return "";
  const auto scaled = [](const std::vector<double>& v, double k) {
    std::vector<double> out(v.size());
    std::transform(v.begin(), v.end(), out.begin(), [k](double x) { return k * x; });
    return out;
  };
  const Style r_style{"#1b2a49", 1.0, false}, t_style{"#e07b39", 1.0, false}, n_style{"#2e8b57", 1.0, false};
  Figure figure("fig-navigation", kWidth, 230.0, 2);
  for (const auto& [name, nav] : {std::pair{"OSC", &run.navigation_osc}, std::pair{"DSC", &run.navigation_dsc}}) {
    const std::vector<double> t = hours(nav->t_s);
    Plot& position = figure.add(Plot(fmt::format("{} filter: relative antenna position error", name), "time [h]", "[mm]"));
    position.line("R", t, scaled(nav->antenna_r, 1e3), r_style)
        .line("T", t, scaled(nav->antenna_t, 1e3), t_style)
        .line("N", t, scaled(nav->antenna_n, 1e3), n_style);
    add_time_marks(position, run);
    Plot& velocity = figure.add(Plot(fmt::format("{} filter: relative velocity error", name), "time [h]", "[mm/s]"));
    velocity.line("R", t, scaled(nav->v_r, 1e3), r_style)
        .line("T", t, scaled(nav->v_t, 1e3), t_style)
        .line("N", t, scaled(nav->v_n, 1e3), n_style);
    add_time_marks(velocity, run);
  }
  const NavigationSeries& osc = run.navigation_osc;
  const std::vector<double> t = hours(osc.t_s);
  Plot& empirical = figure.add(Plot("OSC filter: empirical accelerations", "time [h]", "[\u03bcm/s\u00b2]"));
  empirical.line("DSC R", t, scaled(osc.emp_dsc_r, 1e6), Style{"#1b2a49", 0.8, true})
      .line("DSC T", t, scaled(osc.emp_dsc_t, 1e6), Style{"#e07b39", 0.8, true})
      .line("OSC R", t, scaled(osc.emp_osc_r, 1e6), r_style)
      .line("OSC T", t, scaled(osc.emp_osc_t, 1e6), t_style);
  add_time_marks(empirical, run);
  Plot& fixed = figure.add(Plot("integer ambiguity resolution", "time [h]", "epochs fixed [%]"));
  fixed.step("OSC filter", t, scaled(osc.fixed_fraction, 100.0), r_style)
      .step("DSC filter", hours(run.navigation_dsc.t_s), scaled(run.navigation_dsc.fixed_fraction, 100.0), t_style);
  add_time_marks(fixed, run);
  return wrap("fig-navigation", figure.svg("on-board navigation errors, empirical accelerations and fix status"),
              "On-board carrier-phase GPS navigation against the truth, every output step: the relative position of "
              "the GPS antennas (the centres of mass's knowledge error removed) and the relative velocity, each "
              "filter in the chief's RTN axes; the empirical accelerations the OSC's filter estimates; the "
              "fraction of the processed epochs with a fixed integer solution since the previous sample. "
              "Vertical lines: observation starts and mode changes.");
}

std::string all_figures(const RunData& run) {
  return roe_figure(run) + ei_vector_figure(run) + separation_figure(run) + trajectory_figure(run) +
         alignment_figure(run) + navigation_figure(run) + delta_v_figure(run) + drag_figure(run) +
         mode_figure(run);
}

}  // namespace visors::report
