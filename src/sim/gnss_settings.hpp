#pragma once
// The [gnss] tables of a scenario file: where the GPS constellation comes from, the receivers'
// and the broadcast errors' settings, and what `visors gnss-sim` simulates and writes.
//
//   [gnss]
//   nav_file = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx"  # data search path, or a path
//   source_time_gps = "2024-05-07T12:00:00"  # records nearest this are moved to the start time
//   duration_s = 5400.0      # gnss-sim span [s]
//   rinex = true             # gnss-sim writes RINEX 3 observation and navigation files
//   attitude = "nominal"     # or "observation" (payload +X at the Sun the whole time)
//   [gnss.receiver]          # sim/gps_receiver.hpp, angles in deg / arcsec
//   elevation_mask_deg, channels, code_sigma_m, phase_sigma_m, doppler_sigma_hz,
//   clock_step_sigma_m, initial_clock_sigma_m, phase_center_offset_m, mounting_sigma_arcsec,
//   antenna_body_m = [x, y, z], occultation_altitude_m, cycle_slip_probability, max_slip_cycles,
//   ionosphere, topside_fraction, shell_height_m, unflagged_slip_fraction,
//   half_cycle_slip_probability, half_cycle_resolve_s, elevation_dependent_noise, code_multipath_m,
//   phase_multipath_m, multipath_tau_s, data_gap_probability, data_gap_s
//   [gnss.broadcast_errors]  # sim/gps_satellite_truth.hpp
//   radial_m, along_m, cross_m, clock_m, clock_drift_sps

#include <string>

#include <toml++/toml.h>

#include "core/status.hpp"
#include "sim/gps_receiver.hpp"
#include "sim/gps_satellite_truth.hpp"

namespace visors::sim {

struct GnssSettings {
  std::string nav_file = "gnss/NYA100NOR_S_20241280000_01D_GN.rnx";
  std::string source_time_gps = "2024-05-07T12:00:00";
  double duration_s = 5400.0;
  bool rinex = true;
  std::string attitude = "nominal";
  GpsReceiverSettings receiver;  // its Klobuchar coefficients come from the navigation file
  BroadcastErrorSettings broadcast_errors;
};

/// Reads root["gnss"] (absent: the defaults) into `settings`; unknown keys and bad values are
/// errors naming "gnss.<table>.<key>".
core::Result<bool> read_gnss_settings(const toml::table& root, GnssSettings& settings);

/// The [gnss] tables with every value written out (re-readable by read_gnss_settings).
std::string gnss_settings_to_toml(const GnssSettings& settings);

}  // namespace visors::sim
