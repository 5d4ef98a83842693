#include "report/report.hpp"

#include <fstream>

#include <fmt/core.h>

#include "report/html_text.hpp"
#include "report/report_figures.hpp"
#include "report/report_tables.hpp"
#include "report/run_directory.hpp"
#include "report/summary_fields.hpp"

namespace visors::report {
namespace {

// Inline so the file opens anywhere, offline, exactly as written.
constexpr const char* kStyle = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; margin: 24px auto; max-width: 1000px;
       color: #222; background: #fff; }
h1 { font-size: 1.5em; margin-bottom: 0.2em; }
h2 { font-size: 1.2em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; margin-top: 1.6em; }
.subtitle { color: #666; margin-top: 0; }
figure { margin: 1.5em 0; }
figcaption { font-size: 0.85em; color: #444; margin-top: 0.3em; }
svg { display: block; max-width: 100%; height: auto; font-family: inherit; font-size: 11px; }
svg text { fill: #333; }
svg .panel-title { font-weight: bold; font-size: 12px; }
svg .axis-label { font-size: 11px; }
svg .grid { stroke: #eee; stroke-width: 1; }
svg .frame { fill: none; stroke: #888; stroke-width: 1; }
svg .marker { opacity: 0.7; }
svg .no-data { fill: #999; font-style: italic; }
table { border-collapse: collapse; font-size: 0.85em; margin: 0.5em 0; }
th, td { border: 1px solid #ddd; padding: 3px 8px; text-align: right; }
th { background: #f4f4f4; }
td:first-child { text-align: left; }
table.summary td { text-align: left; }
#events td:nth-child(n+3), #events th:nth-child(n+3) { text-align: left; }
#events td:last-child { white-space: pre-wrap; }
td.pass { color: #1e7d3c; font-weight: bold; }
td.fail { color: #b22222; font-weight: bold; }
tr.requirement td { color: #666; font-style: italic; }
p.none { color: #888; font-style: italic; }
p.note { font-size: 0.8em; color: #666; }
)css";

std::string head(const RunData& run) {
  const std::string scenario = summary_text(run.summary, {"scenario"});
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>VISORS run report \u2013 {}</title>\n<style>{}</style>\n</head>\n",
      escape_html(scenario), kStyle);
}

}  // namespace

std::string render_report(const RunData& run) {
  std::string html = head(run);
  html += "<body>\n<h1>VISORS formation-flying run report</h1>\n";
  html += fmt::format("<p class=\"subtitle\">scenario {}, t0 {}, {} samples</p>\n",
                      escape_html(summary_text(run.summary, {"scenario"})),
                      escape_html(summary_text(run.summary, {"t0", "iso"})), run.timeseries.size());
  html += summary_box(run);
  html += "<section id=\"figures\"><h2>Figures</h2>\n" + all_figures(run) + "</section>\n";
  html += delta_v_table(run);
  html += observation_table(run);
  html += event_table(run);
  html += "</body>\n</html>\n";
  return html;
}

core::Result<std::string> render_report(const std::filesystem::path& run_dir) {
  auto run = load_run(run_dir);
  if (!run) return run.error();
  return render_report(run.value());
}

core::Result<std::filesystem::path> write_report(const std::filesystem::path& run_dir) {
  auto html = render_report(run_dir);
  if (!html) return html.error();
  const std::filesystem::path path = run_dir / kReportFile;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << html.value();
  out.close();
  if (!out) return core::Error{path.string(), "cannot be written"};
  return path;
}

}  // namespace visors::report
