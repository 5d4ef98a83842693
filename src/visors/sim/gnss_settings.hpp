#pragma once
// The [gnss] tables of a scenario file: where the GPS constellation comes from, the receivers'
// and the broadcast errors' settings, and what `visors gnss-sim` simulates and writes.
//
//   [gnss]
//   nav_file = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx"  # data search path, or a path
//   source_time_gps = "2024-05-07T12:00:00"  # records nearest this are moved to the start time
//   duration_s = 5400.0      # gnss-sim span [s]
//   rinex = true             # gnss-sim writes RINEX 3 observation and navigation files
//   attitude = "nominal"     # or "observation" (payload +X at the Sun the whole time), or
//                            # "campaign" (nominal, one observation per orbit with its slews)
//   [gnss.receiver]          # sim/gps_receiver.hpp, angles in deg / arcsec
//   elevation_mask_deg, channels, code_sigma_m, phase_sigma_m, doppler_sigma_hz,
//   clock_step_sigma_m, initial_clock_sigma_m, phase_center_offset_m, mounting_sigma_arcsec,
//   antenna_body_m = [x, y, z], occultation_altitude_m, cycle_slip_probability, max_slip_cycles,
//   ionosphere, topside_fraction, shell_height_m, unflagged_slip_fraction,
//   half_cycle_slip_probability, half_cycle_resolve_s, elevation_dependent_noise, code_multipath_m,
//   phase_multipath_m, multipath_tau_s, data_gap_probability, data_gap_s
//   [gnss.broadcast_errors]  # sim/gps_satellite_truth.hpp
//   radial_m, along_m, cross_m, clock_m, clock_drift_sps
//   [gnss.observations]      # the windows of attitude = "campaign" (read always)
//   first_start_s = 1500.0   # start of the first observation [s after t0]; its slew must start
//                            # at or after t0 (first_start_s >= the slew lead)
//   period_s = 0.0           # between observations [s]; 0: the chief's Keplerian period from
//                            # [chief] a_m, 2 pi sqrt(a^3 / mu)
//   duration_s = 10.0        # of each observation [s] (paper: 10-s observations)
//   slew_lead_s = 0.0        # slew start before start_s [s]; 0: AttitudeProfile::
//                            # required_slew_lead_s(pi) (a 180 deg slew plus settling, 150 s)
//   [gnss.maneuvers]         # a maneuver schedule (sim/gnss_simulation.hpp)
//   spacecraft = "none"      # or "osc", "dsc", "both"
//   bursts_per_orbit = 3     # bursts evenly spaced by period / bursts_per_orbit (period above)
//   pieces_per_burst = 4     # pieces 46.5 s apart ([propulsion] spacing)
//   dv_mps = 0.002           # commanded |dv| of each piece [m/s]
//   first_burst_s = 900.0    # first piece of the first burst [s after t0]
//   keeping = false          # true: each piece also carries a tangential formation-keeping
//                            # correction from the TRUE states (perfect knowledge, a test harness:
//                            # sim/formation_keeping.hpp) holding the initial mean ROE's dlambda
//   (the propulsion model is the scenario's: [propulsion] and the spacecraft's mass_kg and
//   propellant_kg, as in `visors run`)
//   [gnss.lrf]               # laser rangefinder OSC -> DSC, during observations only
//   enabled = false          # true needs attitude = "campaign"
//   interval_s = 2.0         # between measurements [s] (paper: every 2 s), a multiple of step_s
//   sigma_m = 0.002          # white noise 1-sigma [m]
//   bias_m = 0.0             # true constant bias (not calibrated) [m]

#include <string>

#include <toml++/toml.h>

#include "visors/core/result.hpp"
#include "visors/sim/gps_receiver.hpp"
#include "visors/sim/gps_satellite_truth.hpp"

namespace visors::sim {

/// [gnss.observations]: windows start_k = first_start_s + k period_s, k = 0, 1, ...
struct GnssObservationSettings {
  double first_start_s = 1500.0;  // [s after t0]
  double period_s = 0.0;          // [s]; 0: the chief's Keplerian period
  double duration_s = 10.0;       // [s]
  double slew_lead_s = 0.0;       // [s]; 0: AttitudeProfile::required_slew_lead_s(pi)
};

/// [gnss.maneuvers] (sim/gnss_simulation.hpp: directions, skipping, execution).
struct GnssManeuverSettings {
  std::string spacecraft = "none";  // "none", "osc", "dsc" or "both"
  int bursts_per_orbit = 3;
  int pieces_per_burst = 4;
  double dv_mps = 0.002;         // commanded |dv| per piece [m/s]
  double first_burst_s = 900.0;  // [s after t0]
  bool keeping = false;          // tangential formation-keeping correction (sim/formation_keeping.hpp)
};

/// [gnss.lrf]: laser rangefinder between the true payload points, during observations.
struct GnssLrfSettings {
  bool enabled = false;
  double interval_s = 2.0;  // [s]
  double sigma_m = 0.002;   // [m]
  double bias_m = 0.0;      // [m]
};

struct GnssSettings {
  std::string nav_file = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";
  std::string source_time_gps = "2024-05-07T12:00:00";
  double duration_s = 5400.0;
  bool rinex = true;
  std::string attitude = "nominal";
  GpsReceiverSettings receiver;  // its Klobuchar coefficients come from the navigation file
  BroadcastErrorSettings broadcast_errors;
  GnssObservationSettings observations;
  GnssManeuverSettings maneuvers;
  GnssLrfSettings lrf;
};

/// Reads root["gnss"] (absent: the defaults) into `settings`; unknown keys and bad values are
/// errors naming "gnss.<table>.<key>".
core::Result<bool> read_gnss_settings(const toml::table& root, GnssSettings& settings);

/// The [gnss] tables with every value written out (re-readable by read_gnss_settings).
std::string gnss_settings_to_toml(const GnssSettings& settings);

}  // namespace visors::sim
