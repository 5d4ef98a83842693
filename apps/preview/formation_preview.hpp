#pragma once
// `visors preview`: the relative motion of the mission's formations over a few orbits, with
// no control and no navigation (those come with the simulator). For each formation it writes
// an ephemeris CSV and returns a summary: separations, passive-safety margin in the RN plane,
// how far the linear ROE model (J2 STM + eccentric ROE->RTN map) is from the exact nonlinear
// osculating motion, and the Sun-alignment geometry of the science orbit.

#include <filesystem>
#include <string>
#include <vector>

#include "visors/core/result.hpp"
#include "apps/preview/preview_scenario.hpp"

namespace visors::preview {

struct FormationSummary {
  std::string name;
  std::filesystem::path csv;
  double min_separation_m = 0.0;       // min |r_rel| over the run (nonlinear osculating) [m]
  double max_separation_m = 0.0;       // [m]
  double min_rn_separation_m = 0.0;    // min sqrt(R^2 + N^2) (nonlinear osculating) [m]
  double max_model_error_m = 0.0;      // max |r_rel(linear mean model) - r_rel(nonlinear osc)| [m]
  double drift_along_track_m_per_orbit = 0.0;  // a*dlambda drift of the mean ROE [m/orbit]
  double best_sun_alignment_deg = 0.0; // min angle between r_rel and the Sun direction [deg]
  double best_sun_alignment_time_s = 0.0;       // since epoch [s]
  double separation_at_best_alignment_m = 0.0;  // [m]
};

struct PreviewSummary {
  double chief_period_s = 0.0;         // Keplerian period of the mean chief [s]
  double beta_angle_deg = 0.0;         // Sun elevation above the chief orbit plane at epoch [deg]
  bool eop_used = false;
  std::string eop_note;
  std::vector<FormationSummary> formations;
};

core::Result<PreviewSummary> run_formation_preview(const PreviewScenario& scenario,
                                                   const std::filesystem::path& out_dir);

}  // namespace visors::preview
