#include "visors/report/report.hpp"

#include <fstream>

#include <fmt/core.h>

#include "visors/report/html_text.hpp"
#include "visors/report/report_figures.hpp"
#include "visors/report/report_tables.hpp"
#include "visors/report/run_directory.hpp"
#include "visors/report/summary_fields.hpp"

namespace visors::report {
namespace {


std::string head(const RunData& run) {
  const std::string scenario = summary_text(run.summary, {"scenario"});
  return fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>VISORS run report \u2013 {}</title>\n<style>{}</style>\n</head>\n",
      escape_html(scenario), report_stylesheet());
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
  html += budget_table(run);
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
