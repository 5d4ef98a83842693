#pragma once
// File names and column names of a run directory (docs/run-directory.md), shared by the
// simulator's recorder and the report, so neither can drift from the other.

#include <array>
#include <string_view>

namespace visors::report {

inline constexpr std::string_view kScenarioFile = "scenario.toml";
inline constexpr std::string_view kTimeseriesFile = "timeseries.csv";
inline constexpr std::string_view kObservationsFile = "observations.csv";
inline constexpr std::string_view kEventsFile = "events.csv";
inline constexpr std::string_view kSummaryFile = "summary.json";
inline constexpr std::string_view kReportFile = "report.html";
inline constexpr std::string_view kNavigationFile = "navigation.csv";  // [navigation] mode = "cdgps" only
inline constexpr std::string_view kAlignmentSamplesFile = "alignment_samples.csv";
inline constexpr std::string_view kFlightConfigFile = "flight_config.json";

/// The columns of alignment_samples.csv: every step inside an observation window, the truth the
/// score used (GCRF, centres of mass, body-to-GCRF quaternions scalar first, the target's apparent
/// unit direction from the DSC), in order.
inline constexpr std::array<std::string_view, 28> kAlignmentSampleColumns{
    "index",      "t_s",        "dsc_x_m",    "dsc_y_m",    "dsc_z_m",    "dsc_vx_mps", "dsc_vy_mps",
    "dsc_vz_mps", "dsc_qw",     "dsc_qx",     "dsc_qy",     "dsc_qz",     "osc_x_m",    "osc_y_m",
    "osc_z_m",    "osc_vx_mps", "osc_vy_mps", "osc_vz_mps", "osc_qw",     "osc_qx",     "osc_qy",
    "osc_qz",     "target_x",   "target_y",   "target_z",   "lateral_m",  "lateral_velocity_mps", "focus_m"};

/// The columns of timeseries.csv, in order.
inline constexpr std::array<std::string_view, 30> kTimeseriesColumns{
    "t_s",         "mode",        "active",     "ada_mean_m",      "adl_mean_m", "adex_mean_m", "adey_mean_m",
    "adix_mean_m", "adiy_mean_m", "ada_osc_m",  "adl_osc_m",       "adex_osc_m", "adey_osc_m",  "adix_osc_m",
    "adiy_osc_m",  "r_r_m",       "r_t_m",      "r_n_m",           "v_r_mps",    "v_t_mps",     "v_n_mps",
    "sep_rn_m",    "sep_3d_m",    "safety_margin_m", "dv_dsc_mps", "dv_osc_mps", "drag_area_dsc_m2",
    "drag_area_osc_m2", "drag_t_difference_mps2", "drag_t_estimate_mps2"};

/// The columns of observations.csv and events.csv, in order.
inline constexpr std::array<std::string_view, 6> kObservationColumns{
    "index", "t_s", "lateral_error_m", "lateral_velocity_mps", "focus_error_m", "success"};
/// The columns observations.csv carries after kObservationColumns (figures beside the score, which
/// the report does not need): the worst angle over the window between each spacecraft's true
/// payload line of sight (drawn mounting tilt, ADCS control error) and the target's apparent
/// direction [arcsec].
inline constexpr std::array<std::string_view, 2> kObservationPointingColumns{"payload_pointing_dsc_arcsec",
                                                                            "payload_pointing_osc_arcsec"};
/// The error budget's columns after the pointing (sim/error_budget.hpp): per term (navigation,
/// phase_centre, geometry, target_direction, last_burn, drag_prediction, control_other) its
/// lateral x, y and focus [m] and lateral velocity x, y [m/s] at the worst lateral sample; empty
/// without on-board navigation.
inline constexpr std::array<std::string_view, 35> kObservationBudgetColumns{
    "budget_navigation_x_m", "budget_navigation_y_m", "budget_navigation_focus_m",
    "budget_navigation_velocity_x_mps", "budget_navigation_velocity_y_mps", "budget_phase_centre_x_m",
    "budget_phase_centre_y_m", "budget_phase_centre_focus_m", "budget_phase_centre_velocity_x_mps",
    "budget_phase_centre_velocity_y_mps", "budget_geometry_x_m", "budget_geometry_y_m",
    "budget_geometry_focus_m", "budget_geometry_velocity_x_mps", "budget_geometry_velocity_y_mps",
    "budget_target_direction_x_m", "budget_target_direction_y_m", "budget_target_direction_focus_m",
    "budget_target_direction_velocity_x_mps", "budget_target_direction_velocity_y_mps",
    "budget_last_burn_x_m", "budget_last_burn_y_m", "budget_last_burn_focus_m",
    "budget_last_burn_velocity_x_mps", "budget_last_burn_velocity_y_mps", "budget_drag_prediction_x_m",
    "budget_drag_prediction_y_m", "budget_drag_prediction_focus_m", "budget_drag_prediction_velocity_x_mps",
    "budget_drag_prediction_velocity_y_mps", "budget_control_other_x_m",
    "budget_control_other_y_m", "budget_control_other_focus_m", "budget_control_other_velocity_x_mps",
    "budget_control_other_velocity_y_mps"};

inline constexpr std::array<std::string_view, 4> kEventColumns{"t_s", "spacecraft", "kind", "detail"};

/// The columns of navigation.csv (each component's on-board navigation against the truth, one
/// row per spacecraft every output step; sim/navigation_score.hpp), in order.
inline constexpr std::array<std::string_view, 24> kNavigationColumns{
    "t_s",          "spacecraft",    "fixed",        "fixed_fraction", "rel_r_m",        "rel_t_m",
    "rel_n_m",      "antenna_r_m",   "antenna_t_m",  "antenna_n_m",    "rel_vr_mps",     "rel_vt_mps",
    "rel_vn_mps",   "sigma_r_m",     "sigma_t_m",    "sigma_n_m",      "emp_dsc_r_mps2", "emp_dsc_t_mps2",
    "emp_dsc_n_mps2", "emp_osc_r_mps2", "emp_osc_t_mps2", "emp_osc_n_mps2", "in_slew", "in_observation"};

}  // namespace visors::report
