#pragma once
// A small SVG plotting kit for the report: a Plot is one panel (axes with ticks and labels, line,
// step, curve and marker series, horizontal requirement lines, vertical event markers, coloured
// bands, a legend); a Figure lays panels out in a grid and writes one <svg>. Written for the
// report rather than taken from a library because the report must be a single file with no
// scripts and no network access. Long series are reduced to what the pixels can show
// (decimate.hpp) while the SVG is written, so callers pass their data as is.

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace visors::report {

struct Style {
  std::string colour = "#1f3b73";
  double width = 1.3;
  bool dashed = false;
};

enum class MarkerShape { kCircle, kCross };

/// The pixel rectangle a panel is drawn into.
struct Box {
  double x = 0.0;
  double y = 0.0;
  double width = 0.0;
  double height = 0.0;
};

class Plot {
 public:
  Plot(std::string title, std::string x_label, std::string y_label);

  /// A line through (x, y) with x non-decreasing (a time series); NaN breaks the line.
  Plot& line(std::string label, std::span<const double> x, std::span<const double> y, Style style);
  /// A staircase: y holds from each x to the next (a mode, a counter).
  Plot& step(std::string label, std::span<const double> x, std::span<const double> y, Style style);
  /// A parametric curve (a trajectory in a plane): any order of points.
  Plot& curve(std::string label, std::span<const double> x, std::span<const double> y, Style style);
  /// Unconnected markers.
  Plot& markers(std::string label, std::span<const double> x, std::span<const double> y, MarkerShape shape,
                std::string colour);
  /// A horizontal line across the panel (a requirement, a threshold); it is kept inside the y range.
  Plot& hline(double y, std::string label, Style style);
  /// Vertical lines at each x (observation times, mode changes); not part of the y range.
  Plot& vlines(std::span<const double> x, std::string label, Style style);
  /// A filled rectangle in data coordinates, under the series; an empty label keeps it out of the
  /// legend (a mode drawn as many bands has one entry).
  Plot& band(double x0, double x1, double y0, double y1, std::string colour, std::string label);
  /// Tick labels at given y values instead of numbers (categories).
  Plot& y_categories(std::vector<std::pair<double, std::string>> ticks);
  /// Tick labels at given x values instead of numbers (a sweep's values drawn side by side).
  Plot& x_categories(std::vector<std::pair<double, std::string>> ticks);
  Plot& x_range(double lo, double hi);
  Plot& y_range(double lo, double hi);
  /// Same scale on both axes (a trajectory or an e/i-vector plane keeps its shape).
  Plot& equal_aspect();
  /// Room for the y tick labels, in pixels (long category names need more than numbers).
  Plot& left_margin(double pixels);

  /// The panel as an SVG group; `clip_id` must be unique in the document.
  [[nodiscard]] std::string render(const Box& box, const std::string& clip_id) const;

 private:
  enum class Kind { kLine, kStep, kCurve, kMarkers };
  struct Series {
    Kind kind;
    std::string label;
    std::vector<double> x, y;
    Style style;
    MarkerShape shape = MarkerShape::kCircle;
  };
  struct HLine {
    double y;
    std::string label;
    Style style;
  };
  struct VLines {
    std::vector<double> x;
    std::string label;
    Style style;
  };
  struct Band {
    double x0, x1, y0, y1;
    std::string colour, label;
  };
  struct Ranges {
    double x_lo, x_hi, y_lo, y_hi;
  };

  [[nodiscard]] Ranges ranges(const Box& area) const;
  [[nodiscard]] std::string render_axes(const Box& area, const Ranges& r) const;
  [[nodiscard]] std::string render_data(const Box& area, const Ranges& r) const;
  [[nodiscard]] std::string render_series(const Series& s, const Box& area, const Ranges& r) const;
  // The legend above the plot area; `rows` receives the number of rows it needed.
  [[nodiscard]] std::string render_legend(const Box& box, int& rows) const;
  [[nodiscard]] bool has_data() const;

  std::string title_, x_label_, y_label_;
  std::vector<Series> series_;
  std::vector<HLine> hlines_;
  std::vector<VLines> vlines_;
  std::vector<Band> bands_;
  std::vector<std::pair<double, std::string>> y_categories_, x_categories_;
  std::optional<std::pair<double, double>> x_range_, y_range_;
  bool equal_aspect_ = false;
  double left_margin_;
};

class Figure {
 public:
  /// `columns` panels per row, each `panel_height` pixels high, across `width` pixels.
  Figure(std::string id, double width, double panel_height, int columns);
  Plot& add(Plot plot);
  /// The `<svg>` element, with `id` and an accessible `description`.
  [[nodiscard]] std::string svg(const std::string& description) const;

 private:
  std::string id_;
  double width_;
  double panel_height_;
  int columns_;
  std::vector<Plot> panels_;
};

/// Round tick positions covering [lo, hi] (steps of 1, 2 or 5 times a power of ten).
std::vector<double> nice_ticks(double lo, double hi, int target_count);
/// A tick label with as many decimals as the tick step needs.
std::string tick_label(double value, double step);

}  // namespace visors::report
