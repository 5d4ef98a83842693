#include "visors/report/decimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <utility>

namespace visors::report {
namespace {

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

using Cell = std::pair<std::int64_t, std::int64_t>;

Cell cell_of(const Point& p, double cell) {
  return {static_cast<std::int64_t>(std::floor(p.x / cell)), static_cast<std::int64_t>(std::floor(p.y / cell))};
}

// Appends the representatives of the points of one pixel column to `out`.
void append_column(std::span<const Point> column, std::vector<Point>& out) {
  std::size_t lo = 0;
  std::size_t hi = 0;
  for (std::size_t i = 1; i < column.size(); ++i) {
    if (column[i].y < column[lo].y) lo = i;
    if (column[i].y > column[hi].y) hi = i;
  }
  std::size_t picks[4] = {0, std::min(lo, hi), std::max(lo, hi), column.size() - 1};
  for (std::size_t k = 0; k < 4; ++k) {
    if (k > 0 && picks[k] == picks[k - 1]) continue;
    out.push_back(column[picks[k]]);
  }
}

std::vector<std::vector<Point>> thin_curve_once(std::span<const Point> run, double cell) {
  std::vector<std::vector<Point>> lines;
  std::set<std::pair<Cell, Cell>> drawn;
  if (run.empty()) return lines;
  Cell last = cell_of(run[0], cell);
  lines.push_back({run[0]});
  bool pen_down = true;
  for (std::size_t i = 1; i < run.size(); ++i) {
    const Cell here = cell_of(run[i], cell);
    if (here == last) continue;
    // An undirected segment: the same stretch retraced backwards is also a repeat.
    const auto key = last < here ? std::make_pair(last, here) : std::make_pair(here, last);
    if (!drawn.insert(key).second) {
      pen_down = false;
    } else {
      if (!pen_down) lines.push_back({run[i - 1]});  // restart where the new segment begins
      lines.back().push_back(run[i]);
      pen_down = true;
    }
    last = here;
  }
  // A lone starting point with no segment is still a visible dot only if it is the whole curve.
  if (lines.size() > 1) std::erase_if(lines, [](const std::vector<Point>& l) { return l.size() < 2; });
  return lines;
}

}  // namespace

std::vector<std::vector<Point>> split_at_gaps(std::span<const Point> points) {
  std::vector<std::vector<Point>> runs;
  bool in_run = false;
  for (const Point& p : points) {
    if (!finite(p)) {
      in_run = false;
      continue;
    }
    if (!in_run) runs.emplace_back();
    runs.back().push_back(p);
    in_run = true;
  }
  return runs;
}

std::vector<Point> decimate_columns(std::span<const Point> run, double x_min, double x_max) {
  std::vector<Point> out;
  const auto column_of = [&](const Point& p) {
    return static_cast<std::int64_t>(std::floor(std::clamp(p.x, x_min - 1.0, x_max + 1.0)));
  };
  std::size_t begin = 0;
  while (begin < run.size()) {
    const std::int64_t column = column_of(run[begin]);
    std::size_t end = begin + 1;
    while (end < run.size() && column_of(run[end]) == column) ++end;
    append_column(run.subspan(begin, end - begin), out);
    begin = end;
  }
  return out;
}

std::vector<std::vector<Point>> thin_curve(std::span<const Point> run, double cell, std::size_t max_points) {
  double size = std::max(cell, 1e-3);
  while (true) {
    auto lines = thin_curve_once(run, size);
    // A grid coarse enough holds the curve in a handful of cells, so the loop ends.
    if (point_count(lines) <= max_points || run.empty() || size > 1e9) return lines;
    size *= 2.0;
  }
}

std::vector<Point> thin_markers(std::span<const Point> points, double cell) {
  std::vector<Point> kept;
  std::set<Cell> occupied;
  for (const Point& p : points) {
    if (finite(p) && occupied.insert(cell_of(p, cell)).second) kept.push_back(p);
  }
  return kept;
}

std::size_t point_count(const std::vector<std::vector<Point>>& polylines) {
  std::size_t n = 0;
  for (const auto& line : polylines) n += line.size();
  return n;
}

}  // namespace visors::report
