// The SVG plot builder: ticks, escaping, and a bounded number of drawn points.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "visors/report/svg_plot.hpp"

namespace visors::report {
namespace {

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + what.size())) ++n;
  return n;
}

TEST(SvgPlot, NiceTicks) {
  const auto ticks = nice_ticks(-0.13, 0.92, 5);
  ASSERT_FALSE(ticks.empty());
  // steps of 1, 2 or 5 x 10^k (svg_plot.hpp); loose: measured 0 (2026-11), bound 1e-12 ~4e4x above round-off (ulp(0.2) 2.8e-17)
  EXPECT_NEAR(ticks[1] - ticks[0], 0.2, 1e-12);
  // ticks inside the input range [-0.13, 0.92]; measured first 0, last 0.8 (2026-11)
  EXPECT_GE(ticks.front(), -0.13);
  EXPECT_LE(ticks.back(), 0.92);
  EXPECT_EQ(tick_label(0.4, 0.2), "0.4");
  EXPECT_EQ(tick_label(1500.0, 500.0), "1500");
  EXPECT_EQ(tick_label(0.0, 0.05), "0.00");
  EXPECT_TRUE(nice_ticks(1.0, 1.0, 5).empty());
}

TEST(SvgPlot, EscapesLabelsAndDrawsEverything) {
  Figure figure("fig-test", 600.0, 300.0, 1);
  const std::vector<double> x{0.0, 1.0, 2.0};
  const std::vector<double> y{1.0, 3.0, 2.0};
  figure.add(Plot("a <b> & \"c\"", "t [h]", "[m]"))
      .line("series <1>", x, y, Style{})
      .markers("ok", x, y, MarkerShape::kCircle, "#080")
      .markers("bad", x, y, MarkerShape::kCross, "#800")
      .hline(2.5, "limit", Style{"#f00", 1.0, true})
      .vlines(std::vector<double>{0.5, 1.5}, "event", Style{});
  const std::string svg = figure.svg("test & figure");
  EXPECT_NE(svg.find("<svg id=\"fig-test\""), std::string::npos);
  EXPECT_NE(svg.find("a &lt;b&gt; &amp; &quot;c&quot;"), std::string::npos);
  EXPECT_NE(svg.find("series &lt;1&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("<b>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"series\""), 3u);
  EXPECT_EQ(count(svg, "class=\"threshold\""), 1u);
  EXPECT_EQ(count(svg, "class=\"marker\""), 1u);
}

TEST(SvgPlot, LongSeriesAreDecimated) {
  std::vector<double> t, y;
  for (int i = 0; i < 20000; ++i) {
    t.push_back(10.0 * i);
    y.push_back(std::sin(0.011 * i));
  }
  Figure figure("fig-long", 500.0, 250.0, 1);
  figure.add(Plot("long", "t", "y")).line("y", t, y, Style{});
  const std::string svg = figure.svg("long");
  // 500 px minus margins leaves ~424 columns: at most 4 points each.
  const std::size_t points = count(svg, "L") + count(svg, "M");
  EXPECT_LT(points, 4u * 430u);
  // lower bound chosen (about one point per column); size bound chosen; measured 918 points, 12607 bytes (2026-11)
  EXPECT_GT(points, 400u);
  EXPECT_LT(svg.size(), 40000u);
}

TEST(SvgPlot, EmptyPanelSaysNone) {
  Figure figure("fig-empty", 400.0, 200.0, 1);
  figure.add(Plot("nothing", "x", "y")).markers("m", std::vector<double>{}, std::vector<double>{},
                                                MarkerShape::kCircle, "#000");
  const std::string svg = figure.svg("empty");
  EXPECT_NE(svg.find(">none</text>"), std::string::npos);
  EXPECT_EQ(svg.find("class=\"series\""), std::string::npos);
}

}  // namespace
}  // namespace visors::report
