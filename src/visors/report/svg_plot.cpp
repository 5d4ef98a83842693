#include "visors/report/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <tuple>

#include <fmt/core.h>

#include "visors/report/decimate.hpp"
#include "visors/report/html_text.hpp"

namespace visors::report {
namespace {

// Panel margins in pixels: room for the title and legend above, tick labels and axis labels
// left and below.
constexpr double kDefaultMarginLeft = 62.0;
constexpr double kMarginRight = 14.0;
constexpr double kMarginTop = 29.0;  // plus one legend row height per legend row
constexpr double kLegendRow = 13.0;
constexpr double kMarginBottom = 38.0;
// Budget of a parametric curve (points per panel) and the grid its points are snapped to (px).
constexpr std::size_t kCurvePointBudget = 12000;
constexpr double kCurveCell = 1.0;
constexpr double kMarkerRadius = 2.6;
// A rough width of one character of the 11 px sans-serif font, for laying out the legend.
constexpr double kCharWidth = 6.6;

struct Map {  // data -> pixel: x grows to the right, y upwards (SVG's y grows downwards)
  double x0, sx, y0, sy;
  [[nodiscard]] Point operator()(double x, double y) const { return {x0 + x * sx, y0 - y * sy}; }
};

Map make_map(const Box& area, double x_lo, double x_hi, double y_lo, double y_hi) {
  const double sx = area.width / (x_hi - x_lo);
  const double sy = area.height / (y_hi - y_lo);
  return {area.x - x_lo * sx, sx, area.y + area.height + y_lo * sy, sy};
}

std::vector<Point> to_pixels(std::span<const double> x, std::span<const double> y, const Map& map) {
  std::vector<Point> points;
  const std::size_t n = std::min(x.size(), y.size());
  points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) points.push_back(map(x[i], y[i]));
  return points;
}

void append_polyline(std::string& d, const std::vector<Point>& line) {
  for (std::size_t i = 0; i < line.size(); ++i) {
    fmt::format_to(std::back_inserter(d), "{}{:.1f} {:.1f}", i == 0 ? 'M' : 'L', line[i].x, line[i].y);
  }
  if (line.size() == 1) d += "h0.1";  // a lone point still shows as a dot with round caps
}

std::string dash_attribute(const Style& style) { return style.dashed ? " stroke-dasharray=\"5 3\"" : ""; }

std::string path_element(const std::string& d, const Style& style, const char* cls) {
  return fmt::format(
      "<path class=\"{}\" d=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\" "
      "stroke-linejoin=\"round\" stroke-linecap=\"round\"{}/>\n",
      cls, d, escape_html(style.colour), style.width, dash_attribute(style));
}

std::string marker_path(const std::vector<Point>& points, MarkerShape shape) {
  std::string d;
  const double r = kMarkerRadius;
  for (const Point& p : points) {
    if (shape == MarkerShape::kCircle) {
      fmt::format_to(std::back_inserter(d), "M{:.1f} {:.1f}a{} {} 0 1 0 {} 0a{} {} 0 1 0 {} 0", p.x - r, p.y, r, r,
                     2 * r, r, r, -2 * r);
    } else {
      fmt::format_to(std::back_inserter(d), "M{:.1f} {:.1f}l{} {}m0 {}l{} {}", p.x - r, p.y - r, 2 * r, 2 * r,
                     -2 * r, -2 * r, 2 * r);
    }
  }
  return d;
}

// The finite extent of some values, widened by `lo`/`hi` so far.
void extend(std::span<const double> values, double& lo, double& hi) {
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
}

// An empty or degenerate extent made drawable: a flat line sits in the middle of the panel.
void make_drawable(double& lo, double& hi) {
  if (!(lo <= hi)) {
    lo = 0.0;
    hi = 1.0;
  } else if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) {
    const double pad = std::abs(lo) > 0.0 ? 0.1 * std::abs(lo) : 1.0;
    lo -= pad;
    hi += pad;
  }
}

std::string text_element(double x, double y, const std::string& anchor, const std::string& text,
                         const std::string& extra = "") {
  return fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"{}\"{}>{}</text>\n", x, y, anchor, extra,
                     escape_html(text));
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  std::vector<double> ticks;
  if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  const double raw = (hi - lo) / std::max(1, target_count);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double norm = raw / magnitude;
  const double step = (norm < 1.5 ? 1.0 : norm < 3.0 ? 2.0 : norm < 7.0 ? 5.0 : 10.0) * magnitude;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1.0) {
    ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);  // no "-0"
  }
  return ticks;
}

std::string tick_label(double value, double step) {
  const double magnitude = std::max(std::abs(value), step);
  if (magnitude >= 1e6 || step < 1e-5) return fmt::format("{:.3g}", value);
  const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9)));
  return fmt::format("{:.{}f}", value, decimals);
}

Plot::Plot(std::string title, std::string x_label, std::string y_label)
    : title_(std::move(title)),
      x_label_(std::move(x_label)),
      y_label_(std::move(y_label)),
      left_margin_(kDefaultMarginLeft) {}

Plot& Plot::line(std::string label, std::span<const double> x, std::span<const double> y, Style style) {
  series_.push_back({Kind::kLine, std::move(label), {x.begin(), x.end()}, {y.begin(), y.end()}, std::move(style)});
  return *this;
}

Plot& Plot::step(std::string label, std::span<const double> x, std::span<const double> y, Style style) {
  series_.push_back({Kind::kStep, std::move(label), {x.begin(), x.end()}, {y.begin(), y.end()}, std::move(style)});
  return *this;
}

Plot& Plot::curve(std::string label, std::span<const double> x, std::span<const double> y, Style style) {
  series_.push_back({Kind::kCurve, std::move(label), {x.begin(), x.end()}, {y.begin(), y.end()}, std::move(style)});
  return *this;
}

Plot& Plot::markers(std::string label, std::span<const double> x, std::span<const double> y, MarkerShape shape,
                    std::string colour) {
  Style style{std::move(colour), shape == MarkerShape::kCross ? 1.6 : 1.2, false};
  series_.push_back({Kind::kMarkers, std::move(label), {x.begin(), x.end()}, {y.begin(), y.end()}, style, shape});
  return *this;
}

Plot& Plot::hline(double y, std::string label, Style style) {
  if (std::isfinite(y)) hlines_.push_back({y, std::move(label), std::move(style)});
  return *this;
}

Plot& Plot::vlines(std::span<const double> x, std::string label, Style style) {
  vlines_.push_back({{x.begin(), x.end()}, std::move(label), std::move(style)});
  return *this;
}

Plot& Plot::band(double x0, double x1, double y0, double y1, std::string colour, std::string label) {
  bands_.push_back({x0, x1, y0, y1, std::move(colour), std::move(label)});
  return *this;
}

Plot& Plot::y_categories(std::vector<std::pair<double, std::string>> ticks) {
  y_categories_ = std::move(ticks);
  return *this;
}

Plot& Plot::x_categories(std::vector<std::pair<double, std::string>> ticks) {
  x_categories_ = std::move(ticks);
  return *this;
}

Plot& Plot::x_range(double lo, double hi) {
  x_range_ = {lo, hi};
  return *this;
}

Plot& Plot::y_range(double lo, double hi) {
  y_range_ = {lo, hi};
  return *this;
}

Plot& Plot::equal_aspect() {
  equal_aspect_ = true;
  return *this;
}

Plot& Plot::left_margin(double pixels) {
  left_margin_ = pixels;
  return *this;
}

bool Plot::has_data() const {
  for (const Series& s : series_) {
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) return true;
    }
  }
  return !bands_.empty();
}

Plot::Ranges Plot::ranges(const Box& area) const {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Ranges r{kInf, -kInf, kInf, -kInf};
  for (const Series& s : series_) {
    extend(s.x, r.x_lo, r.x_hi);
    extend(s.y, r.y_lo, r.y_hi);
  }
  for (const Band& b : bands_) {
    extend(std::initializer_list<double>{b.x0, b.x1}, r.x_lo, r.x_hi);
    extend(std::initializer_list<double>{b.y0, b.y1}, r.y_lo, r.y_hi);
  }
  for (const HLine& h : hlines_) extend(std::initializer_list<double>{h.y}, r.y_lo, r.y_hi);
  make_drawable(r.x_lo, r.x_hi);
  make_drawable(r.y_lo, r.y_hi);
  // A little air around the data, except on a time axis, which starts and ends with the run.
  const bool time_axis = std::all_of(series_.begin(), series_.end(),
                                     [](const Series& s) { return s.kind == Kind::kLine || s.kind == Kind::kStep; });
  const double pad_x = time_axis ? 0.0 : 0.05 * (r.x_hi - r.x_lo);
  const double pad_y = 0.06 * (r.y_hi - r.y_lo);
  r.x_lo -= pad_x;
  r.x_hi += pad_x;
  r.y_lo -= pad_y;
  r.y_hi += pad_y;
  if (x_range_) std::tie(r.x_lo, r.x_hi) = *x_range_;
  if (y_range_) std::tie(r.y_lo, r.y_hi) = *y_range_;
  if (equal_aspect_) {
    // Widen the tighter axis so one metre spans the same pixels both ways.
    const double scale = std::max((r.x_hi - r.x_lo) / area.width, (r.y_hi - r.y_lo) / area.height);
    const double cx = 0.5 * (r.x_lo + r.x_hi);
    const double cy = 0.5 * (r.y_lo + r.y_hi);
    r.x_lo = cx - 0.5 * scale * area.width;
    r.x_hi = cx + 0.5 * scale * area.width;
    r.y_lo = cy - 0.5 * scale * area.height;
    r.y_hi = cy + 0.5 * scale * area.height;
  }
  return r;
}

std::string Plot::render_axes(const Box& area, const Ranges& r) const {
  const Map map = make_map(area, r.x_lo, r.x_hi, r.y_lo, r.y_hi);
  std::string out;
  const double bottom = area.y + area.height;
  std::vector<std::pair<double, std::string>> x_ticks = x_categories_;
  if (x_ticks.empty()) {
    const auto values = nice_ticks(r.x_lo, r.x_hi, std::max(2, static_cast<int>(area.width / 80.0)));
    const double x_step = values.size() > 1 ? values[1] - values[0] : 1.0;
    for (const double v : values) x_ticks.emplace_back(v, tick_label(v, x_step));
  }
  for (const auto& [t, label] : x_ticks) {
    const double px = map(t, 0.0).x;
    out += fmt::format("<line class=\"grid\" x1=\"{0:.1f}\" y1=\"{1:.1f}\" x2=\"{0:.1f}\" y2=\"{2:.1f}\"/>\n", px,
                       area.y, bottom);
    out += text_element(px, bottom + 14.0, "middle", label);
  }
  std::vector<std::pair<double, std::string>> y_ticks = y_categories_;
  if (y_ticks.empty()) {
    const auto values = nice_ticks(r.y_lo, r.y_hi, std::max(2, static_cast<int>(area.height / 40.0)));
    const double y_step = values.size() > 1 ? values[1] - values[0] : 1.0;
    for (const double v : values) y_ticks.emplace_back(v, tick_label(v, y_step));
  }
  for (const auto& [v, label] : y_ticks) {
    const double py = map(0.0, v).y;
    out += fmt::format("<line class=\"grid\" x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\"/>\n", area.x,
                       py, area.x + area.width, py);
    out += text_element(area.x - 5.0, py + 4.0, "end", label);
  }
  out += fmt::format("<rect class=\"frame\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/>\n",
                     area.x, area.y, area.width, area.height);
  out += text_element(area.x + 0.5 * area.width, bottom + 31.0, "middle", x_label_, " class=\"axis-label\"");
  const double ly = area.y + 0.5 * area.height;
  out += text_element(area.x - left_margin_ + 13.0, ly, "middle", y_label_,
                      fmt::format(" class=\"axis-label\" transform=\"rotate(-90 {:.1f} {:.1f})\"",
                                  area.x - left_margin_ + 13.0, ly));
  return out;
}

std::string Plot::render_series(const Series& s, const Box& area, const Ranges& r) const {
  const Map map = make_map(area, r.x_lo, r.x_hi, r.y_lo, r.y_hi);
  if (s.kind == Kind::kMarkers) {
    const auto points = thin_markers(to_pixels(s.x, s.y, map), 1.0);
    if (points.empty()) return {};
    const std::string d = marker_path(points, s.shape);
    if (s.shape == MarkerShape::kCircle) {
      return fmt::format("<path class=\"series\" d=\"{}\" fill=\"{}\" stroke=\"{}\" stroke-width=\"0.8\"/>\n", d,
                         escape_html(s.style.colour), escape_html(s.style.colour));
    }
    return path_element(d, s.style, "series");
  }
  std::vector<double> x = s.x;
  std::vector<double> y = s.y;
  if (s.kind == Kind::kStep) {
    // A staircase is a line through the corners: (x_i, y_i) then (x_{i+1}, y_i).
    std::vector<double> sx, sy;
    for (std::size_t i = 0; i < std::min(x.size(), y.size()); ++i) {
      if (i > 0 && std::isfinite(y[i - 1]) && std::isfinite(y[i])) {
        sx.push_back(x[i]);
        sy.push_back(y[i - 1]);
      }
      sx.push_back(x[i]);
      sy.push_back(y[i]);
    }
    x = std::move(sx);
    y = std::move(sy);
  }
  std::string d;
  for (const auto& run : split_at_gaps(to_pixels(x, y, map))) {
    if (s.kind == Kind::kCurve) {
      for (const auto& piece : thin_curve(run, kCurveCell, kCurvePointBudget)) append_polyline(d, piece);
    } else {
      append_polyline(d, decimate_columns(run, area.x, area.x + area.width));
    }
  }
  return d.empty() ? std::string{} : path_element(d, s.style, "series");
}

std::string Plot::render_data(const Box& area, const Ranges& r) const {
  const Map map = make_map(area, r.x_lo, r.x_hi, r.y_lo, r.y_hi);
  std::string out;
  for (const Band& b : bands_) {
    const Point p0 = map(b.x0, b.y1);
    const Point p1 = map(b.x1, b.y0);
    out += fmt::format(
        "<rect class=\"band\" x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\"/>\n", p0.x,
        p0.y, std::max(0.5, p1.x - p0.x), p1.y - p0.y, escape_html(b.colour));
  }
  for (const VLines& v : vlines_) {
    // One short path; markers closer than a pixel would be drawn on top of each other.
    std::vector<double> columns;
    for (const double x : v.x) {
      if (std::isfinite(x)) columns.push_back(std::round(map(x, 0.0).x * 2.0) / 2.0);
    }
    std::sort(columns.begin(), columns.end());
    columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
    std::string d;
    for (const double px : columns) {
      fmt::format_to(std::back_inserter(d), "M{:.1f} {:.1f}V{:.1f}", px, area.y, area.y + area.height);
    }
    if (!d.empty()) out += path_element(d, v.style, "marker");
  }
  for (const Series& s : series_) out += render_series(s, area, r);
  for (const HLine& h : hlines_) {
    const double py = map(0.0, h.y).y;
    out += path_element(fmt::format("M{:.1f} {:.1f}H{:.1f}", area.x, py, area.x + area.width), h.style, "threshold");
  }
  return out;
}

std::string Plot::render_legend(const Box& box, int& rows) const {
  // Entries in the order series, thresholds, markers, bands; each label once.
  struct Entry {
    std::string label;
    Style style;
    int kind;  // 0 line, 1 marker circle, 2 marker cross, 3 band
  };
  std::vector<Entry> entries;
  const auto add = [&entries](const std::string& label, const Style& style, int kind) {
    if (label.empty()) return;
    for (const Entry& e : entries) {
      if (e.label == label) return;
    }
    entries.push_back({label, style, kind});
  };
  for (const Series& s : series_) {
    const int kind = s.kind != Kind::kMarkers ? 0 : s.shape == MarkerShape::kCircle ? 1 : 2;
    add(s.label, s.style, kind);
  }
  for (const HLine& h : hlines_) add(h.label, h.style, 0);
  for (const VLines& v : vlines_) add(v.label, v.style, 0);
  for (const Band& b : bands_) add(b.label, Style{b.colour, 1.0, false}, 3);
  std::string out;
  double x = box.x + left_margin_;
  double y = box.y + 31.0;
  rows = 1;
  for (const Entry& e : entries) {
    const double width = 36.0 + kCharWidth * static_cast<double>(e.label.size());
    if (x + width > box.x + box.width && x > box.x + left_margin_) {  // wrap onto a new row
      x = box.x + left_margin_;
      y += kLegendRow;
      ++rows;
    }
    const Point c{x + 9.0, y - 4.0};
    if (e.kind == 0) {
      out += path_element(fmt::format("M{:.1f} {:.1f}h18", x, c.y), e.style, "legend-line");
    } else if (e.kind == 3) {
      out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"18\" height=\"9\" fill=\"{}\"/>\n", x, c.y - 4.5,
                         escape_html(e.style.colour));
    } else {
      const MarkerShape shape = e.kind == 1 ? MarkerShape::kCircle : MarkerShape::kCross;
      const std::string d = marker_path({c}, shape);
      out += e.kind == 1 ? fmt::format("<path d=\"{}\" fill=\"{}\"/>\n", d, escape_html(e.style.colour))
                         : path_element(d, e.style, "legend-line");
    }
    out += text_element(x + 22.0, y, "start", e.label, " class=\"legend\"");
    x += width;
  }
  return out;
}

std::string Plot::render(const Box& box, const std::string& clip_id) const {
  // The legend is laid out first: a legend that wraps pushes the plot area down.
  int legend_rows = 1;
  const std::string legend = render_legend(box, legend_rows);
  const double top = kMarginTop + kLegendRow * legend_rows;
  const Box area{box.x + left_margin_, box.y + top, box.width - left_margin_ - kMarginRight,
                 box.height - top - kMarginBottom};
  const Ranges r = ranges(area);
  std::string out = "<g class=\"panel\">\n";
  out += text_element(box.x + left_margin_, box.y + 15.0, "start", title_, " class=\"panel-title\"");
  out += legend;
  out += render_axes(area, r);
  out += fmt::format("<clipPath id=\"{}\"><rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\"/></clipPath>\n",
                     escape_html(clip_id), area.x, area.y, area.width, area.height);
  out += fmt::format("<g clip-path=\"url(#{})\">\n", escape_html(clip_id));
  out += render_data(area, r);
  out += "</g>\n";
  if (!has_data()) {
    out += text_element(area.x + 0.5 * area.width, area.y + 0.5 * area.height, "middle", "none",
                        " class=\"no-data\"");
  }
  return out + "</g>\n";
}

Figure::Figure(std::string id, double width, double panel_height, int columns)
    : id_(std::move(id)), width_(width), panel_height_(panel_height), columns_(std::max(1, columns)) {}

Plot& Figure::add(Plot plot) {
  panels_.push_back(std::move(plot));
  return panels_.back();
}

std::string Figure::svg(const std::string& description) const {
  const std::size_t columns = static_cast<std::size_t>(columns_);
  const std::size_t rows = (panels_.size() + columns - 1) / columns;
  const double height = static_cast<double>(std::max<std::size_t>(rows, 1)) * panel_height_;
  const double panel_width = width_ / static_cast<double>(columns);
  std::string out = fmt::format(
      "<svg id=\"{0}\" xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {1} {2}\" width=\"{1}\" height=\"{2}\" "
      "role=\"img\" aria-label=\"{3}\">\n",
      escape_html(id_), width_, height, escape_html(description));
  for (std::size_t i = 0; i < panels_.size(); ++i) {
    const Box box{static_cast<double>(i % columns) * panel_width, static_cast<double>(i / columns) * panel_height_,
                  panel_width, panel_height_};
    out += panels_[i].render(box, fmt::format("{}-clip-{}", id_, i));
  }
  return out + "</svg>\n";
}

}  // namespace visors::report
