#pragma once
// Helpers shared by the report tests: the <svg> element of a figure in an HTML text, and whether
// it draws data.

#include <string>
#include <string_view>

namespace visors::test {

/// The text from `<svg id="ID"` to its `</svg>`; empty when absent.
inline std::string figure_svg(const std::string& html, std::string_view id) {
  const std::string start = "<svg id=\"" + std::string(id) + "\"";
  const std::size_t begin = html.find(start);
  if (begin == std::string::npos) return {};
  const std::size_t end = html.find("</svg>", begin);
  return end == std::string::npos ? std::string{} : html.substr(begin, end - begin);
}

/// True when `svg` holds a data path (class "series") whose d has at least two commands, or a
/// polyline with points.
inline bool draws_data(const std::string& svg) {
  for (std::size_t pos = svg.find("<path"); pos != std::string::npos; pos = svg.find("<path", pos + 1)) {
    const std::size_t close = svg.find('>', pos);
    const std::string element = svg.substr(pos, close - pos);
    if (element.find("class=\"series\"") == std::string::npos) continue;
    const std::size_t d = element.find(" d=\"M");
    if (d != std::string::npos && element.find_first_of("LlaVH", d + 5) != std::string::npos) return true;
  }
  const std::size_t polyline = svg.find("<polyline");
  return polyline != std::string::npos && svg.find("points=\"", polyline) != std::string::npos;
}

}  // namespace visors::test
