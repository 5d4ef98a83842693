#pragma once
// The mission-campaign scenario of `visors run` (TOML; data/scenarios/campaign.toml is the default,
// the test case of Guffanti et al., AAS 23-149, 2023, Table 5): the chief orbit, the initial
// formation, the campaign timeline (standby, then science with N attempts, then back to standby),
// navigation, propulsion, crosslink, the two spacecraft, the truth forces, faults and outputs.
// Every key is optional (defaults below and in the structs they fill); unknown keys and
// out-of-range values are errors naming the dotted key.

#include <cstdint>
#include <string>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/dynamics/force_model_config.hpp"
#include "visors/gnc/gnc_config.hpp"
#include "visors/sim/adcs_model.hpp"
#include "visors/sim/attitude_profile.hpp"
#include "visors/sim/gnss_settings.hpp"
#include "visors/sim/host_clock.hpp"
#include "visors/sim/propulsion.hpp"
#include "visors/sim/spacecraft_geometry.hpp"

namespace visors::sim {

/// Where the flight components' navigation comes from ([navigation] mode).
enum class NavigationMode {
  kIdeal,  // the truth plus Gauss-Markov errors (sim/ideal_navigation.hpp), for control-only studies
  kCdgps,  // each component's own carrier-phase differential GPS filter (gnc/onboard_navigation.hpp)
};

struct NavigationErrorSettings {
  /// 3D 1-sigma errors of the ideal navigation (defaults: relative 1 cm, 50 um/s; absolute 5 m,
  /// 1 cm/s: the DiGiTaL IAR-on figures of Guffanti et al., AAS 23-149, 2023, Table 3).
  double relative_position_m = 0.01;
  double relative_velocity_mps = 5e-5;
  double absolute_position_m = 5.0;
  double absolute_velocity_mps = 0.01;
  /// Correlation time of the first-order Gauss-Markov errors (a filter's error is correlated
  /// in time, not white) [s].
  double correlation_time_s = 600.0;
};

/// One spacecraft of the truth ([dsc], [osc]): its nominal design values and the 1-sigma of the
/// per-run deviation of its true values from them (sim/truth_dynamics.hpp draw_true_spacecraft).
/// The flight software knows the nominal values from its own configuration ([flight]), never
/// from these keys (docs/truth-and-knowledge.md).
struct SpacecraftSettings {
  double mass_kg = 11.35;        // wet mass at start [kg]
  double propellant_kg = 0.378;  // [kg] (DSC: 14.6 m/s at Isp 44 s; OSC 0.205 kg for 8.4 m/s)
  double cd = 2.2;
  double cr = 1.8;
  double srp_area_m2 = 0.35;
  double mass_sigma_kg = 0.05;  // a weighed CubeSat with a gauged tank: 0.5 % [kg] (ours)
  double cd_sigma = 0.22;       // 10 %: free-molecular Cd of a flat-panel body, 2.0-2.4 (ours)
  double cr_sigma = 0.18;       // 10 %: the optical properties' ageing and the panels (ours)
};

/// What the flight software is told of both spacecraft ([flight]): the flight team's values,
/// with their defaults the design's. The on-board force models and each component's own mass
/// come from here.
struct FlightKnowledge {
  double dsc_mass_kg = 11.35;  // [kg]
  double osc_mass_kg = 10.62;  // [kg]
  double cd = 2.2;
  double cr = 1.8;
  double drag_area_m2 = 0.35;  // the mean of the attitudes' 0.15-0.55 m^2
  double srp_area_m2 = 0.35;
  /// The IERS file the ground uplinks the Earth orientation at the start from (data-relative or
  /// absolute; empty or not found: zero EOP). The truth's own is [forces] earth_frame.eop.
  std::string eop_file = "eop/finals2000A_2024-07-01_2025-01-31.txt";
  /// The GPS antenna as calibrated (one design on both spacecraft), body frame: its reference
  /// point from the nominal centre of mass and the phase-centre offset along the boresight +Z [m]
  /// (the truth's: [gnss.receiver] antenna_body_m, phase_center_offset_m, and the drawn errors).
  Eigen::Vector3d antenna_arp_body_m = Eigen::Vector3d(0.0, 0.0, 0.1);
  double antenna_pco_m = 0.0854;
  /// The rangefinder (OSC) and its target (DSC), each from its centre of mass, body frame [m];
  /// its noise and calibrated bias [m] (the truth's: the drawn payload points, [gnss.lrf]).
  Eigen::Vector3d lrf_lever_body_m = Eigen::Vector3d(0.15, 0.0, 0.0);
  double lrf_sigma_m = 0.002;
  double lrf_bias_m = 0.0;
};

/// A fault that lasts: from start_s [s since t0] for duration_s [s]; disabled when start_s < 0.
struct FaultWindow {
  double start_s = -1.0;
  double duration_s = 0.0;
  [[nodiscard]] bool contains(double t_s) const { return start_s >= 0.0 && t_s >= start_s && t_s < start_s + duration_s; }
};

struct FaultSettings {
  /// An unplanned impulse of the OSC (a stuck valve), to force a passive-safety violation;
  /// disabled when t_s < 0.
  double impulse_t_s = -1.0;
  Eigen::Vector3d impulse_dv_rtn_mps = Eigen::Vector3d::Zero();
  /// A non-GNC fault reported to the host application at this time (e.g. a bus safe mode of the
  /// passive spacecraft); disabled when < 0. The host's response (Guffanti et al., AAS 23-149,
  /// 2023, sec. 4.1, FDIR): transfer
  /// to standby when the formation is in science or transfer, otherwise a role switch.
  double non_gnc_fault_t_s = -1.0;
  // The fault windows of the fault scenarios (data/scenarios/faults; each handled by the host's
  // FDIR as sim/campaign_simulation.hpp says); the spacecraft concerned is the one active when the
  // window opens.
  FaultWindow gps_outage;      // its receiver delivers nothing; every satellite re-acquired after
  FaultWindow crosslink_loss;  // every crosslink message lost, both ways
  FaultWindow safe_mode;       // its bus in safe mode: its component is not stepped
  FaultWindow garbage;         // bursts of garbage and NaN records on every input channel of both
  double thruster_failure_t_s = -1.0;  // from then its propulsion executes nothing
  double clock_jump_t_s = -1.0;        // its receiver clock jumps by clock_jump_m then
  double clock_jump_m = 0.0;           // c x the jump [m] (receivers steer by 1 ms: 299,792.458 m)
};

struct CampaignScenario {
  std::string name = "visors_campaign";
  std::uint64_t seed = 1;
  core::GpsTime t0;                        // start (GPS), default 2024-10-01 00:00:00
  astro::KeplerianElements chief_mean;     // DSC mean elements at t0
  Eigen::Matrix<double, 6, 1> initial_roe_m = Eigen::Matrix<double, 6, 1>::Zero();  // a * mean ROE [m]
  // Timeline.
  double standby_s = 2700.0;       // standby before the science command (paper: 45 min) [s]
  int observations = 10;
  double tail_s = 1800.0;          // run on this long after the formation is back in standby [s]
  double max_duration_s = 250000.0;  // hard stop [s]
  double step_s = 1.0;             // simulation and GNC step (the 1 Hz channels) [s]
  double output_step_s = 10.0;     // time-series sampling [s]
  std::string active = "osc";      // initially active spacecraft
  /// The commanded observation target ([campaign] target_offset_arcsec): standard coordinates (xi
  /// east, eta north) about the apparent Sun centre [rad]. A ground command, given to both flight
  /// components (gnc.science.geometry.target_offset_rad) and scored against by the truth.
  Eigen::Vector2d target_offset_rad = Eigen::Vector2d::Zero();
  // Models.
  NavigationMode navigation_mode = NavigationMode::kCdgps;
  NavigationErrorSettings navigation;  // ideal navigation's errors
  /// The [nav] table as given (the on-board filter's tunables over its defaults,
  /// config/cdgps_settings_toml.hpp), empty when absent; checked when the scenario is read.
  std::string nav_toml;
  PropulsionSettings propulsion;
  SpacecraftSettings dsc;
  SpacecraftSettings osc;
  FlightKnowledge flight;  // [flight]: what the flight software is told
  /// Truth geometry errors of both spacecraft ([geometry]; the nominal points are not scenario
  /// keys): centre-of-mass variation and knowledge error, payload mounting and pointing.
  GeometrySettings geometry;
  /// The bus ADCS of both spacecraft ([attitude], truth): its slew rate, control error and the
  /// error of the attitude it reports to the flight software (sim/adcs_model.hpp).
  AdcsSettings adcs;
  /// The calibration yaws of both spacecraft's nominal attitude ([attitude] calibration_*; the
  /// commanded attitude, sim/attitude_profile.hpp): 90 deg about the boresight once an orbit.
  CalibrationYaw calibration_yaw{.yaw_rad = 90.0 * core::kDegToRad};
  /// The host computers' time at tone ([clock], truth): the PPS error and the oscillator that
  /// keeps the tone without a receiver solution (sim/host_clock.hpp).
  HostClockSettings host_clock;
  double crosslink_delay_s = 0.5;
  double crosslink_drop_probability = 0.0;
  dynamics::ForceModelConfig forces = dynamics::ForceModelConfig::truth();
  std::string forces_toml = "[forces]\npreset = \"truth\"\n";  // the [forces] table as given (for scenario.toml)
  double integration_step_s = 1.0;  // truth RK4 step (<= step_s) [s]
  FaultSettings fault;
  gnc::GncConfig gnc;  // shared by both components (self, role and mass are set per spacecraft)
  GnssSettings gnss;   // GPS constellation and receivers (visors gnss-sim)
};

/// The step of the timeline at t_s seconds since t0, `step_s` a step, or -1 for a negative
/// (disabled) time: when a timed fault or command happens.
std::int64_t step_at(double t_s, double step_s);

/// The default scenario (the mission test case).
CampaignScenario default_campaign();

/// Parses TOML text over the defaults. Errors name the key ("timeline.observations").
core::Result<CampaignScenario> campaign_from_toml(const std::string& text);

/// The scenario as TOML with every value written out (the run directory's scenario.toml).
std::string campaign_to_toml(const CampaignScenario& scenario);

}  // namespace visors::sim
