// Decimation keeps what the pixels show and bounds the number of points drawn.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "visors/report/decimate.hpp"

namespace visors::report {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(Decimate, ColumnsKeepTheEnvelopeWithAtMostFourPointsPerColumn) {
  // 20,000 samples of a fast oscillation across 400 pixel columns.
  std::vector<Point> points;
  for (int i = 0; i < 20000; ++i) {
    const double x = 10.0 + 400.0 * i / 19999.0;
    points.push_back({x, 100.0 + 50.0 * std::sin(0.37 * i)});
  }
  const auto kept = decimate_columns(points, 10.0, 410.0);
  // decimate.hpp contract: at most 4 points per column, 400 columns plus the two clamped edge columns; lower bound chosen (more than one per column); measured 1550 (2026-11)
  EXPECT_LE(kept.size(), 4u * 402u);
  EXPECT_GT(kept.size(), 400u);
  const auto by_y = [](const Point& a, const Point& b) { return a.y < b.y; };
  EXPECT_EQ(std::min_element(kept.begin(), kept.end(), by_y)->y, std::min_element(points.begin(), points.end(), by_y)->y);
  EXPECT_EQ(std::max_element(kept.begin(), kept.end(), by_y)->y, std::max_element(points.begin(), points.end(), by_y)->y);
  EXPECT_EQ(kept.front().x, points.front().x);
  EXPECT_EQ(kept.back().x, points.back().x);
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end(), [](const Point& a, const Point& b) { return a.x < b.x; }));
}

TEST(Decimate, OffPanelPointsCollapse) {
  std::vector<Point> points;
  for (int i = 0; i < 10000; ++i) points.push_back({-5000.0 + i, 1.0 * (i % 7)});
  // decimate.hpp contract: columns clamped to [x_min - 1, x_max + 1], 103 columns of at most 4 points; measured 108 (2026-11)
  EXPECT_LE(decimate_columns(points, 0.0, 100.0).size(), 4u * 103u);
}

TEST(Decimate, GapsSplitRuns) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point> points{{0, 1}, {1, nan}, {2, 3}, {3, 4}, {nan, 5}, {nan, 6}, {6, 7}};
  const auto runs = split_at_gaps(points);
  ASSERT_EQ(runs.size(), 3u);
  EXPECT_EQ(runs[0].size(), 1u);
  EXPECT_EQ(runs[1].size(), 2u);
  EXPECT_EQ(runs[2].size(), 1u);
}

TEST(Decimate, RetracedCurveIsBounded) {
  // 35 loops of an ellipse 300 px wide, 570 samples per loop, slowly drifting.
  std::vector<Point> points;
  for (int i = 0; i < 35 * 570; ++i) {
    const double u = 2.0 * kPi * i / 570.0;
    points.push_back({200.0 + 150.0 * std::cos(u) + 0.001 * i, 200.0 + 75.0 * std::sin(u)});
  }
  const auto lines = thin_curve(points, 1.0, 4000);
  // the max_points budget (thin_curve, decimate.hpp); lower bound 500 chosen; measured 1809 (2026-11)
  EXPECT_LE(point_count(lines), 4000u);
  EXPECT_GT(point_count(lines), 500u);  // still a curve, not a few dots
  const auto tight = thin_curve(points, 1.0, 300);  // a tiny budget coarsens the grid
  // the max_points budget (thin_curve, decimate.hpp); measured 169 (2026-11)
  EXPECT_LE(point_count(tight), 300u);
  EXPECT_FALSE(tight.empty());
}

TEST(Decimate, MarkersOnePerCell) {
  std::vector<Point> points;
  for (int i = 0; i < 1000; ++i) points.push_back({10.0 + 0.001 * i, 20.0});
  points.push_back({50.0, 50.0});
  EXPECT_EQ(thin_markers(points, 1.0).size(), 2u);  // x in [10, 11): one cell, and (50, 50)
}

}  // namespace
}  // namespace visors::report
