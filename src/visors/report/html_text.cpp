#include "visors/report/html_text.hpp"

#include <cmath>

#include <fmt/core.h>

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

}  // namespace

std::string_view report_stylesheet() { return kStyle; }

std::string standalone_svg(std::string_view svg_element) {
  const std::size_t open_end = svg_element.find('>');
  if (open_end == std::string_view::npos) return std::string(svg_element);
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += svg_element.substr(0, open_end + 1);
  out += "\n<style>\n";
  out += kStyle;
  out += "</style>\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>";
  out += svg_element.substr(open_end + 1);
  return out;
}

std::string escape_html(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out.push_back(c);
    }
  }
  return out;
}

std::string format_fixed(double value, int decimals) {
  if (!std::isfinite(value)) return "\u2013";
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace visors::report
