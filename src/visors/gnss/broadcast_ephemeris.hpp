#pragma once
// One GPS LNAV broadcast ephemeris and clock record (subframes 1-3), and the user algorithm that
// turns it into the satellite's Earth-fixed position, velocity and clock: IS-GPS-200 (Rev. N)
// Table 20-IV (position), 20.3.3.3.3.1 (clock polynomial and relativistic correction),
// 20.3.3.3.3.2 (L1 group delay). The velocity is the exact time derivative of the same equations
// (the rate form that IS-GPS-200 Table 20-IV gives since Rev. E), so position and velocity are
// consistent to rounding.
//
// The position is the satellite antenna phase centre as the control segment defines it, in
// WGS-84 (ITRF-aligned to ~1 cm) Earth-fixed axes AT THE EPOCH t (the transmission time when used
// for ranging); a receiver at another epoch rotates it by the Earth's rotation over the light time.

#include "visors/core/status.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/satellite_state.hpp"

namespace visors::gnss {

struct BroadcastEphemeris {
  int prn = 0;                  // 1..32
  core::GpsTime toc;            // clock reference time
  core::GpsTime toe;            // ephemeris reference time (full week + seconds)
  core::GpsTime transmission;   // when the record was transmitted (ordering of equal t_oe); = toe if unknown
  double af0_s = 0.0;           // clock bias [s]
  double af1_sps = 0.0;         // clock drift [s/s]
  double af2_sps2 = 0.0;        // clock drift rate [s/s^2]
  int iode = 0;                 // issue of data, ephemeris
  int iodc = 0;                 // issue of data, clock
  double sqrt_a = 0.0;          // square root of the semi-major axis [m^(1/2)]
  double eccentricity = 0.0;
  double i0_rad = 0.0;          // inclination at t_oe
  double omega0_rad = 0.0;      // longitude of the ascending node at the weekly epoch
  double omega_rad = 0.0;       // argument of perigee
  double m0_rad = 0.0;          // mean anomaly at t_oe
  double delta_n_radps = 0.0;   // mean motion difference from the computed value [rad/s]
  double idot_radps = 0.0;      // rate of inclination [rad/s]
  double omega_dot_radps = 0.0; // rate of right ascension [rad/s]
  double cuc_rad = 0.0, cus_rad = 0.0;  // argument-of-latitude harmonic corrections
  double crc_m = 0.0, crs_m = 0.0;      // orbit-radius harmonic corrections
  double cic_rad = 0.0, cis_rad = 0.0;  // inclination harmonic corrections
  double tgd_s = 0.0;           // L1-L2 group delay differential T_GD [s]
  int health = 0;               // 6-bit SV health, 0 = all signals OK
  double ura_m = 0.0;           // user range accuracy [m]
  double fit_interval_h = 4.0;  // curve-fit interval [h]; the record is valid within +/- half of it
};

/// Plausibility of the decoded values for a GPS orbit, naming the field: prn in 1..32, every value
/// finite, sqrt_a in [5000, 5300] m^(1/2) (GPS a = 26,560 km; +/- 2,000 km), eccentricity in
/// [0, 0.05], i0 in [45, 70] deg, |omega_dot| < 1e-7 rad/s, |delta_n| and |idot| < 1e-7 rad/s,
/// |harmonic corrections| below 1e-3 rad / 2,000 m, fit interval > 0. A record failing it was
/// corrupted between the satellite and the file (GPS orbits never leave these bounds).
core::Status validate(const BroadcastEphemeris& eph);

/// State at GPS system time t. clock_bias_s = a_f0 + a_f1 dt + a_f2 dt^2 + F e sqrt(A) sin E
/// (dt = t - t_oc), WITHOUT the group delay (see l1_clock_bias_s). Allocation-free; Kepler's
/// equation by Newton iteration from E = M to |dE| < 1e-15 rad (at most 20 steps; e < 0.05
/// converges in 4).
GpsSatelliteState broadcast_state(const BroadcastEphemeris& eph, core::GpsTime t);

/// The clock offset an L1 C/A user applies: clock_bias_s - T_GD (IS-GPS-200 20.3.3.3.3.2).
double l1_clock_bias_s(const BroadcastEphemeris& eph, const GpsSatelliteState& state);

/// |t - t_oe| <= fit_interval / 2.
bool within_fit_interval(const BroadcastEphemeris& eph, core::GpsTime t);

/// How far two records of one satellite are apart, at the midpoint of their t_oe: position and
/// c x clock [m]. Consecutive uploads agree to a few metres; a record carrying another
/// satellite's orbit differs by thousands of km.
struct RecordDisagreement {
  static constexpr double kAgreementM = 1000.0;  // records closer than this in both agree
  double position_m = 0.0;
  double clock_m = 0.0;
  [[nodiscard]] bool agrees() const { return position_m < kAgreementM && clock_m < kAgreementM; }
};
RecordDisagreement disagreement(const BroadcastEphemeris& a, const BroadcastEphemeris& b);

}  // namespace visors::gnss
