#pragma once
// A GPS almanac entry (IS-GPS-200 20.3.3.5.1.2, subframes 4 and 5) and the satellite state it
// gives: the ephemeris user algorithm of Table 20-IV without the harmonic corrections, with
// delta_n = 0 and IDOT = 0, i = i0 directly (IS-GPS-200 20.3.3.5.2.1), clock a_f0 + a_f1 t_k
// (20.3.3.5.2.3). Kilometre-level; used to plan acquisition and by the constellation tools, never
// for ranging.

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/satellite_state.hpp"

namespace visors::gnss {

struct GpsAlmanacEntry {
  int prn = 0;
  int health = 0;             // 8-bit almanac health, 0 = healthy
  double eccentricity = 0.0;
  core::GpsTime toa;          // time of applicability (full week)
  double inclination_rad = 0.0;
  double raan_rate_radps = 0.0;  // Omega dot
  double sqrt_a = 0.0;        // [m^(1/2)]
  double raan_rad = 0.0;      // Omega0: longitude of the ascending node at the weekly epoch
  double arg_perigee_rad = 0.0;
  double mean_anomaly_rad = 0.0;  // at toa
  double af0_s = 0.0;
  double af1_sps = 0.0;
};

/// Field-named plausibility checks (as validate(BroadcastEphemeris) for the shared fields).
core::Status validate(const GpsAlmanacEntry& entry);

/// The entry as a broadcast record with zero corrections (fit interval 240 h).
BroadcastEphemeris to_broadcast(const GpsAlmanacEntry& entry);

/// State at GPS time t (the relativistic clock term included, as for the ephemeris).
GpsSatelliteState almanac_state(const GpsAlmanacEntry& entry, core::GpsTime t);

}  // namespace visors::gnss
