#pragma once
// `visors nav RUN_DIR [--out DIR] [--duration S] [--crosslink-drop P] [--outage START DURATION]
//  [--crosslink-delay S] [--elevation-weighting] [--float] [--no-laser] [--settings FILE]`: replays a `visors gnss-sim` run directory
// through the on-board carrier-phase differential GPS filter (src/visors/nav/cdgps_filter.hpp) of each
// spacecraft at 1 Hz, with the run's commanded impulses and laser ranges (nav_inputs.hpp: what the
// filter reads), and scores it against the run's truth (nav_score.hpp): relative position and
// velocity (OSC minus DSC, RTN of the DSC), absolute position and velocity, fix rate, time to
// first fix, wrong fixes (a full fix whose double-difference integers differ from the truth),
// NEES/NIS, and during observations the payload points' relative error along the line of sight.
// Writes DIR/nav_<craft>.csv (one row per epoch: the scores, and the scored solution's centres of
// mass and antenna phase centres, GCRF), DIR/fixes_<craft>.csv (one row per double-difference
// integer of each full fix), DIR/summary.json (fix rates over the epochs present and over every
// receiver time tag) and DIR/nav.html; formats in docs/run-directory.md.

#include <string>

namespace visors::nav_app {

struct NavOptions {
  std::string run_dir;
  std::string out = "out/nav";
  double duration_s = 0.0;  // 0: the whole run
  bool elevation_weighting = false;  // the filter's CdgpsSettings::elevation_weighting
  bool float_only = false;           // no integer ambiguity resolution (CdgpsSettings::ambiguity_resolution)
  bool no_laser = false;             // the run's laser ranges (lrf.csv) not fused
  std::string settings_file;         // a TOML file with a [nav] table of filter settings
                                     // (config/cdgps_settings_toml.hpp); empty: none
  // Faults injected by the replay (the run's data unchanged otherwise).
  double crosslink_drop = 0.0;   // probability that the other receiver's epoch is lost
  double crosslink_delay_s = 0.0;  // the other receiver's epochs arrive this late [s]: each joint
                                   // epoch is processed then, and its solution scored also there
  double outage_start_s = -1.0;  // GPS outage of both receivers from this time [s]; < 0: none
  double outage_s = 0.0;         // its duration [s]
};

/// The process exit code: 0 on success, 2 on bad input (the message names the option or file),
/// 1 when the outputs cannot be written.
int run_nav_command(const NavOptions& options);

}  // namespace visors::nav_app
