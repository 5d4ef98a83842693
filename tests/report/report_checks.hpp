#pragma once
// Helpers shared by the report tests: the <svg> element of a figure in an HTML text, and whether
// it draws data.

#include <cctype>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
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

/// The distinct points of every data series in `svg`: the coordinate pairs of each
/// `<path class="series" d="...">` (M/L commands with absolute x y pairs, as svg_plot writes them)
/// and of each `<polyline points="...">`.
inline std::set<std::pair<double, double>> plotted_points(const std::string& svg) {
  std::set<std::pair<double, double>> points;
  // Absolute pairs after M and L (and in a points list); the numbers of other commands (the
  // markers' relative arcs and lines, h) are skipped, so a marker counts as its one M point.
  auto read_pairs = [&](const std::string& text, bool polyline) {
    std::string spaced;
    for (char c : text) {
      const bool command = std::isalpha(static_cast<unsigned char>(c)) && c != 'e' && c != 'E';
      spaced += command ? std::string(" ") + c + " " : std::string(1, c == ',' ? ' ' : c);
    }
    std::istringstream in(spaced);
    std::string token;
    bool absolute = polyline;
    std::vector<double> numbers;
    auto flush = [&] {
      for (std::size_t i = 0; absolute && i + 1 < numbers.size(); i += 2) points.emplace(numbers[i], numbers[i + 1]);
      numbers.clear();
    };
    while (in >> token) {
      if (std::isalpha(static_cast<unsigned char>(token[0]))) {
        flush();
        absolute = token == "M" || token == "L";
      } else {
        numbers.push_back(std::stod(token));
      }
    }
    flush();
  };
  auto attribute = [](const std::string& element, const std::string& name) {
    const std::size_t at = element.find(" " + name + "=\"");
    if (at == std::string::npos) return std::string{};
    const std::size_t begin = at + name.size() + 3;
    return element.substr(begin, element.find('"', begin) - begin);
  };
  for (std::size_t pos = svg.find("<path"); pos != std::string::npos; pos = svg.find("<path", pos + 1)) {
    const std::string element = svg.substr(pos, svg.find('>', pos) - pos);
    if (element.find("class=\"series\"") != std::string::npos) read_pairs(attribute(element, "d"), false);
  }
  for (std::size_t pos = svg.find("<polyline"); pos != std::string::npos; pos = svg.find("<polyline", pos + 1)) {
    read_pairs(attribute(svg.substr(pos, svg.find('>', pos) - pos), "points"), true);
  }
  return points;
}

/// True when the data series of `svg` plot at least `min_points` distinct points (an axis frame,
/// a legend swatch or an empty series does not).
inline bool draws_data(const std::string& svg, std::size_t min_points = 3) {
  return plotted_points(svg).size() >= min_points;
}

}  // namespace visors::test
