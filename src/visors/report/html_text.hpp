#pragma once
// Text written into the HTML report: every string that comes from a run directory (modes, event
// details, the scenario name) is escaped, because a detail may hold '<', '&' or quotes, and the
// report must render what was recorded, never interpret it.

#include <string>
#include <string_view>

namespace visors::report {

/// `text` with & < > " ' replaced by entities: safe in element content and in quoted attributes.
std::string escape_html(std::string_view text);

/// The reports' stylesheet (run and Monte Carlo reports), inlined into each page.
std::string_view report_stylesheet();

/// An `<svg>` element of Figure::svg as a file of its own (an image for a README): the
/// stylesheet inlined in a `<style>` and a white background, so it renders outside the page.
std::string standalone_svg(std::string_view svg_element);

/// A number for a table cell: `decimals` after the point, or "–" for NaN/inf (a missing value).
std::string format_fixed(double value, int decimals);

}  // namespace visors::report
