#include "visors/gnss/almanac.hpp"

namespace visors::gnss {

BroadcastEphemeris to_broadcast(const GpsAlmanacEntry& a) {
  BroadcastEphemeris e;
  e.prn = a.prn;
  e.toc = e.toe = e.transmission = a.toa;
  e.af0_s = a.af0_s;
  e.af1_sps = a.af1_sps;
  e.sqrt_a = a.sqrt_a;
  e.eccentricity = a.eccentricity;
  e.i0_rad = a.inclination_rad;
  e.omega0_rad = a.raan_rad;
  e.omega_rad = a.arg_perigee_rad;
  e.m0_rad = a.mean_anomaly_rad;
  e.omega_dot_radps = a.raan_rate_radps;
  e.health = a.health;
  e.fit_interval_h = 240.0;
  return e;
}

core::Status validate(const GpsAlmanacEntry& entry) { return validate(to_broadcast(entry)); }

GpsSatelliteState almanac_state(const GpsAlmanacEntry& entry, core::GpsTime t) {
  return broadcast_state(to_broadcast(entry), t);
}

}  // namespace visors::gnss
