#pragma once
// Reducing long series to what a figure can show. A 35-orbit run sampled every 10 s has ~20,000
// rows; drawn point by point, the eight figures would weigh tens of megabytes, yet a panel a few
// hundred pixels wide cannot show more than a few values per pixel column. All functions work in
// pixel coordinates (after the data -> screen map), so the reduction is tied to what is visible.

#include <cstddef>
#include <span>
#include <vector>

namespace visors::report {

struct Point {
  double x = 0.0;
  double y = 0.0;
};

/// The runs of finite points of `points`: a NaN coordinate (a missing value) ends a run, so a
/// line is broken where data is missing instead of being joined across the gap.
std::vector<std::vector<Point>> split_at_gaps(std::span<const Point> points);

/// Min/max decimation of a run whose x increases (a time series): the points falling in one pixel
/// column (floor of x, clamped to [x_min - 1, x_max + 1] so off-panel points cost nothing) are
/// replaced by the first, the lowest, the highest and the last of them, in their original order.
/// The drawn envelope is the same as with every point, with at most 4 points per column.
std::vector<Point> decimate_columns(std::span<const Point> run, double x_min, double x_max);

/// Thinning of a parametric curve (a trajectory in a plane, which revisits the same places orbit
/// after orbit): points are snapped to a grid of `cell` pixels, consecutive points in the same cell
/// are dropped, and a segment between two cells that was already drawn is skipped (the result is
/// then a set of polylines). If more than `max_points` remain, the grid is coarsened by 2 and the
/// thinning repeated, so the count is bounded whatever the input.
std::vector<std::vector<Point>> thin_curve(std::span<const Point> run, double cell, std::size_t max_points);

/// Markers: one per occupied cell of `cell` pixels (a later marker in the same cell would be drawn
/// over the first).
std::vector<Point> thin_markers(std::span<const Point> points, double cell);

/// Total number of points of a set of polylines.
std::size_t point_count(const std::vector<std::vector<Point>>& polylines);

}  // namespace visors::report
