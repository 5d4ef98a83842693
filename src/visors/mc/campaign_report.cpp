#include "visors/mc/campaign_report.hpp"

#include <cmath>
#include <fstream>
#include <map>

#include <fmt/format.h>

#include "visors/mc/box_statistics.hpp"
#include "visors/report/html_text.hpp"
#include "visors/report/svg_plot.hpp"

namespace visors::mc {
namespace {

using report::escape_html;

constexpr double kRequiredSuccess = 0.20;  // Guffanti et al., AAS 23-149, 2023, sec. 2: >= 20 %
const char* const kPalette[] = {"#1f3b73", "#c0392b", "#27ae60", "#8e44ad", "#d35400", "#16a085", "#7f8c8d", "#2c3e50"};

struct Attempt {
  double lateral_m, lateral_x_m, lateral_y_m, focus_signed_m;
  bool success;
};

// The attempts and runs of one value of one sweep (or of every run, without sweeps).
struct ValueGroup {
  std::string label;
  std::vector<Attempt> attempts;
  std::vector<double> dv_osc_mps, dv_dsc_mps;
  int runs = 0, failed = 0;
  [[nodiscard]] double success_rate() const {
    if (attempts.empty()) return std::nan("");
    int ok = 0;
    for (const Attempt& a : attempts) ok += a.success ? 1 : 0;
    return static_cast<double>(ok) / static_cast<double>(attempts.size());
  }
};

struct SweepGroup {
  std::string key;
  std::vector<ValueGroup> values;  // in the campaign's order (first seen in run order)
};

double number(const nlohmann::json& j, const char* key) {
  const auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<double>() : std::nan("");
}

std::vector<SweepGroup> group(const std::vector<StoredRun>& runs, double& lateral_requirement_m) {
  std::vector<SweepGroup> sweeps;
  std::map<std::pair<std::string, std::string>, std::pair<std::size_t, std::size_t>> where;
  for (const StoredRun& r : runs) {
    const auto key = std::make_pair(r.sweep_key, r.sweep_value_text);
    if (!where.contains(key)) {
      std::size_t s = 0;
      while (s < sweeps.size() && sweeps[s].key != r.sweep_key) ++s;
      if (s == sweeps.size()) sweeps.push_back({r.sweep_key, {}});
      sweeps[s].values.push_back({r.sweep_key.empty() ? "all runs" : r.sweep_value_text, {}, {}, {}, 0, 0});
      where[key] = {s, sweeps[s].values.size() - 1};
    }
    ValueGroup& g = sweeps[where[key].first].values[where[key].second];
    ++g.runs;
    if (!r.ok) {
      ++g.failed;
      continue;
    }
    if (r.summary.contains("requirements")) lateral_requirement_m = number(r.summary["requirements"], "lateral_error_m");
    for (const auto& o : r.summary.value("observations", nlohmann::json::array())) {
      g.attempts.push_back({number(o, "lateral_error_m"), number(o, "lateral_x_m"), number(o, "lateral_y_m"),
                            number(o, "focus_signed_m"), o.value("success", false)});
    }
    const auto dv = r.summary.value("delta_v_mps", nlohmann::json::object());
    g.dv_osc_mps.push_back(number(dv.value("osc", nlohmann::json::object()), "total"));
    g.dv_dsc_mps.push_back(number(dv.value("dsc", nlohmann::json::object()), "total"));
  }
  return sweeps;
}

// Upper panel of the paper's figure: lateral error per value, Tukey boxes [mm]. The axis ends
// above the highest whisker and 2.5x the requirement, so that a few outliers of decimetres do not
// flatten the boxes; the outliers above it are counted in the title.
report::Plot whisker_panel(const SweepGroup& s, double requirement_m) {
  std::vector<BoxStatistics> boxes;
  double top_mm = 2.5e3 * requirement_m;
  for (const ValueGroup& g : s.values) {
    std::vector<double> lateral_mm;
    for (const Attempt& a : g.attempts) lateral_mm.push_back(1e3 * a.lateral_m);
    boxes.push_back(box_statistics(lateral_mm));
    if (boxes.back().count > 0) top_mm = std::max(top_mm, 1.2 * boxes.back().whisker_high);
  }
  std::size_t above = 0;
  for (const BoxStatistics& b : boxes) above += static_cast<std::size_t>(std::count_if(b.outliers.begin(), b.outliers.end(), [&](double v) { return v > top_mm; }));
  std::string title = s.key.empty() ? "Lateral alignment error" : s.key;
  if (above > 0) title += fmt::format(" ({} outlier{} above the axis)", above, above == 1 ? "" : "s");
  report::Plot p(title, s.key.empty() ? "" : "value", "lateral error [mm]");
  std::vector<std::pair<double, std::string>> ticks;
  bool outliers_labelled = false;
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    const double x = static_cast<double>(i);
    ticks.emplace_back(x, s.values[i].label);
    const BoxStatistics& b = boxes[i];
    if (b.count == 0) continue;
    const std::string colour = kPalette[0];
    p.band(x - 0.3, x + 0.3, b.q1, b.q3, "#9db4d8", i == 0 ? "quartiles" : "");
    const std::vector<double> xs{x - 0.3, x + 0.3}, med{b.median, b.median};
    p.curve(i == 0 ? "median" : "", xs, med, {colour, 2.0, false});
    const std::vector<double> xv{x, x}, low{b.whisker_low, b.q1}, high{b.q3, b.whisker_high};
    p.curve("", xv, low, {colour, 1.0, false});
    p.curve("", xv, high, {colour, 1.0, false});
    const std::vector<double> ox(b.outliers.size(), x);
    if (!b.outliers.empty()) {
      p.markers(outliers_labelled ? "" : "outliers", ox, b.outliers, report::MarkerShape::kCross, "#555555");
      outliers_labelled = true;
    }
  }
  p.hline(1e3 * requirement_m, "requirement", {"#c0392b", 1.2, true});
  p.x_categories(ticks).x_range(-0.6, static_cast<double>(s.values.size()) - 0.4).y_range(0.0, top_mm);
  return p;
}

// Lower panel: success percentage per value against the 20 % requirement.
report::Plot success_panel(const SweepGroup& s) {
  report::Plot p("Alignment success", s.key.empty() ? "" : "value", "success [%]");
  std::vector<std::pair<double, std::string>> ticks;
  std::vector<double> x, y;
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    ticks.emplace_back(static_cast<double>(i), s.values[i].label);
    x.push_back(static_cast<double>(i));
    y.push_back(100.0 * s.values[i].success_rate());
  }
  p.line("success", x, y, {kPalette[0], 1.5, false}).markers("", x, y, report::MarkerShape::kCircle, kPalette[0]);
  p.hline(100.0 * kRequiredSuccess, "requirement (20 %)", {"#c0392b", 1.2, true});
  p.x_categories(ticks).x_range(-0.6, static_cast<double>(s.values.size()) - 0.4).y_range(0.0, 100.0);
  return p;
}

// The lateral errors in the detector's frame, one colour per value, the requirement's circle.
report::Plot dispersion_panel(const SweepGroup& s, double requirement_m) {
  report::Plot p(s.key.empty() ? "Lateral error, detector frame" : s.key, "x (vertical) [mm]", "y [mm]");
  for (std::size_t i = 0; i < s.values.size(); ++i) {
    std::vector<double> x, y;
    for (const Attempt& a : s.values[i].attempts) {
      x.push_back(1e3 * a.lateral_x_m);
      y.push_back(1e3 * a.lateral_y_m);
    }
    p.markers(s.values[i].label, x, y, report::MarkerShape::kCircle, kPalette[i % std::size(kPalette)]);
  }
  std::vector<double> cx, cy;
  for (int k = 0; k <= 72; ++k) {
    cx.push_back(1e3 * requirement_m * std::cos(k * M_PI / 36.0));
    cy.push_back(1e3 * requirement_m * std::sin(k * M_PI / 36.0));
  }
  p.curve("requirement", cx, cy, {"#c0392b", 1.2, true}).equal_aspect();
  return p;
}

std::string mean_text(const std::vector<double>& v, double scale) {
  double sum = 0.0;
  int n = 0;
  for (const double x : v) {
    if (std::isnan(x)) continue;
    sum += x;
    ++n;
  }
  return n > 0 ? report::format_fixed(scale * sum / n, 1) : "-";
}

std::string value_table(const SweepGroup& s) {
  std::string t = "<table><tr><th>value</th><th>runs</th><th>failed</th><th>attempts</th><th>success</th>"
                  "<th>median lateral [mm]</th><th>95th pct lateral [mm]</th><th>OSC &Delta;v [mm/s]</th>"
                  "<th>DSC &Delta;v [mm/s]</th></tr>\n";
  for (const ValueGroup& g : s.values) {
    std::vector<double> lateral;
    for (const Attempt& a : g.attempts) lateral.push_back(1e3 * a.lateral_m);
    std::sort(lateral.begin(), lateral.end());
    const double rate = g.success_rate();
    t += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                     escape_html(g.label), g.runs, g.failed, g.attempts.size(),
                     std::isnan(rate) ? "-" : report::format_fixed(100.0 * rate, 0) + " %",
                     lateral.empty() ? "-" : report::format_fixed(percentile(lateral, 50.0), 1),
                     lateral.empty() ? "-" : report::format_fixed(percentile(lateral, 95.0), 1), mean_text(g.dv_osc_mps, 1e3),
                     mean_text(g.dv_dsc_mps, 1e3));
  }
  return t + "</table>\n";
}

std::string failed_table(const std::vector<StoredRun>& runs) {
  std::string t;
  for (const StoredRun& r : runs) {
    if (r.ok) continue;
    t += fmt::format("<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n", r.run,
                     escape_html(r.sweep_key.empty() ? "-" : r.sweep_key + " = " + r.sweep_value_text), r.seed, escape_html(r.error));
  }
  if (t.empty()) return "<p>No run failed.</p>\n";
  return "<table><tr><th>run</th><th>value</th><th>seed</th><th>reason</th></tr>\n" + t + "</table>\n";
}

std::string provenance(const CampaignInfo& info) {
  std::string t = fmt::format("<p>{}; campaign recorded {}; {} runs planned.</p>\n", escape_html(info.program_version),
                              escape_html(info.created_utc), info.total_runs);
  t += "<table><tr><th>data file</th><th>bytes</th><th>FNV-1a 64</th></tr>\n";
  for (const DataFileUse& f : info.data_files) {
    t += fmt::format("<tr><td>{}</td><td>{}</td><td><code>{}</code></td></tr>\n", escape_html(f.path), f.size, f.checksum);
  }
  return t + "</table>\n";
}

// The page; `figures` receives each sweep's sensitivity figure as (file name, <svg> element).
std::string page(const CampaignInfo& info, const std::vector<StoredRun>& runs,
                 std::vector<std::pair<std::string, std::string>>& figures) {
  double requirement_m = 0.018;
  const std::vector<SweepGroup> sweeps = group(runs, requirement_m);
  std::string body;
  int figure = 0;
  for (const SweepGroup& s : sweeps) {
    body += fmt::format("<h2>{}</h2>\n", escape_html(s.key.empty() ? "All runs" : s.key));
    report::Figure sensitivity(fmt::format("sensitivity{}", figure), 900.0, 300.0, 2);
    sensitivity.add(whisker_panel(s, requirement_m));
    sensitivity.add(success_panel(s));
    const std::string svg = sensitivity.svg("Lateral alignment error (whiskers: Tukey, 1.5 IQR) and success percentage per value");
    figures.emplace_back(fmt::format("sensitivity_{}.svg", figure), svg);
    body += svg + "\n";
    report::Figure dispersion(fmt::format("dispersion{}", figure++), 560.0, 480.0, 1);
    dispersion.add(dispersion_panel(s, requirement_m));
    body += dispersion.svg("Lateral alignment error of each attempt in the detector's frame, at its worst sample") + "\n";
    body += value_table(s);
  }
  return fmt::format(R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{0} - Monte Carlo campaign</title>
<style>{7}</style>
</head>
<body>
<h1>{0}</h1>
<p>{1} runs stored of {2}; the mission requires at least 20 % of the attempts to succeed (lateral error
&le; {3} mm, lateral velocity and focus within their budgets).</p>
{4}
<h2>Failed runs</h2>
{5}
<h2>Provenance</h2>
{6}
</body>
</html>
)",
                     escape_html(info.name), runs.size(), info.total_runs, report::format_fixed(1e3 * requirement_m, 0), body,
                     failed_table(runs), provenance(info), report::report_stylesheet());
}

}  // namespace

std::vector<ValueSuccess> success_by_value(const std::vector<StoredRun>& runs) {
  double unused_requirement = 0.0;
  std::vector<ValueSuccess> out;
  for (const SweepGroup& sweep : group(runs, unused_requirement)) {
    for (const ValueGroup& g : sweep.values) {
      ValueSuccess v{sweep.key, g.label, 0, static_cast<long>(g.attempts.size())};
      for (const Attempt& a : g.attempts) v.successes += a.success ? 1 : 0;
      out.push_back(v);
    }
  }
  return out;
}

core::Result<std::filesystem::path> write_campaign_report(ResultsStore& store, const std::filesystem::path& out_dir) {
  auto info = store.info();
  if (!info.ok()) return info.error();
  auto runs = store.runs();
  if (!runs.ok()) return runs.error();
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  const std::filesystem::path path = out_dir / "report.html";
  std::vector<std::pair<std::string, std::string>> figures;
  std::ofstream out(path);
  out << page(*info, *runs, figures);
  if (!out) return core::Error{path.string(), "cannot be written"};
  for (const auto& [name, svg] : figures) {
    std::ofstream file(out_dir / name);
    file << report::standalone_svg(svg);
    if (!file) return core::Error{(out_dir / name).string(), "cannot be written"};
  }
  return path;
}

}  // namespace visors::mc
