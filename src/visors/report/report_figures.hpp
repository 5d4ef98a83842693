#pragma once
// The eight figures of the run report, each a <figure> holding an <svg> with a stable id (tests
// and readers find figures by id) and a <figcaption>.

#include <string>

#include "visors/report/run_data.hpp"

namespace visors::report {

/// The ids of the figures every run has, in the order they appear (a run with on-board navigation
/// also has "fig-navigation", after "fig-alignment").
inline constexpr const char* kFigureIds[] = {"fig-roe-mean-osc", "fig-ei-vectors", "fig-separation",
                                             "fig-trajectory-rtn", "fig-alignment", "fig-delta-v",
                                             "fig-drag",         "fig-modes"};

std::string roe_figure(const RunData& run);
std::string ei_vector_figure(const RunData& run);
std::string separation_figure(const RunData& run);
std::string trajectory_figure(const RunData& run);
std::string alignment_figure(const RunData& run);
std::string delta_v_figure(const RunData& run);
/// The true differential along-track drag and the active spacecraft's on-board estimate of it.
std::string drag_figure(const RunData& run);
std::string mode_figure(const RunData& run);
/// The navigation figures of Guffanti et al., AAS 23-149, 2023, sec. 5 (on-board navigation runs;
/// empty otherwise): each filter's relative antenna position and velocity errors in RTN, the
/// empirical accelerations it estimates, and the fraction of its epochs fixed, with the
/// observations marked.
std::string navigation_figure(const RunData& run);

/// All eight, in order.
std::string all_figures(const RunData& run);

}  // namespace visors::report
