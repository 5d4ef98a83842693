#include "visors/gnss/broadcast_ephemeris.hpp"

#include <cmath>
#include <string>

#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

core::Status validate(const BroadcastEphemeris& e) {
  const double deg = kGpsPi / 180.0;
  const struct {
    const char* field;
    double value;
    double low, high;  // inclusive bounds
  } bounds[] = {
      {"af0", e.af0_s, -1e-2, 1e-2},            // 10 ms: a GPS clock is steered within 1 ms
      {"af1", e.af1_sps, -1e-8, 1e-8},
      {"af2", e.af2_sps2, -1e-12, 1e-12},
      {"sqrt_a", e.sqrt_a, 5000.0, 5300.0},
      {"eccentricity", e.eccentricity, 0.0, 0.05},
      {"i0", e.i0_rad, 45.0 * deg, 70.0 * deg},
      {"omega0", e.omega0_rad, -4.0, 4.0},      // pi, with some tolerance for writers' wrap-around
      {"omega", e.omega_rad, -4.0, 4.0},
      {"m0", e.m0_rad, -4.0, 4.0},
      {"delta_n", e.delta_n_radps, -1e-7, 1e-7},
      {"idot", e.idot_radps, -1e-7, 1e-7},
      {"omega_dot", e.omega_dot_radps, -1e-7, 1e-7},
      {"cuc", e.cuc_rad, -1e-3, 1e-3},
      {"cus", e.cus_rad, -1e-3, 1e-3},
      {"cic", e.cic_rad, -1e-3, 1e-3},
      {"cis", e.cis_rad, -1e-3, 1e-3},
      {"crc", e.crc_m, -2000.0, 2000.0},
      {"crs", e.crs_m, -2000.0, 2000.0},
      {"tgd", e.tgd_s, -1e-6, 1e-6},
  };
  if (e.prn < 1 || e.prn > kMaxGpsPrn) return {core::Problem::kOutOfRange, "prn"};
  for (const auto& b : bounds) {
    if (!std::isfinite(b.value)) return {core::Problem::kNotFinite, b.field};
    if (b.value < b.low || b.value > b.high) return {core::Problem::kOutOfRange, b.field};  // not a GPS orbit or clock
  }
  if (!(e.fit_interval_h > 0.0 && e.fit_interval_h <= 240.0)) return {core::Problem::kOutOfRange, "fit_interval_h"};
  return {};
}

GpsSatelliteState broadcast_state(const BroadcastEphemeris& eph, core::GpsTime t) {
  // IS-GPS-200 Table 20-IV; t_k from full times, so no week wrap is needed.
  const double a = eph.sqrt_a * eph.sqrt_a;
  const double n = std::sqrt(kGpsMu / (a * a * a)) + eph.delta_n_radps;
  const double tk = t.seconds_since(eph.toe);
  const double mk = eph.m0_rad + n * tk;
  const double e = eph.eccentricity;
  double ek = mk;
  for (int iteration = 0; iteration < 20; ++iteration) {
    const double step = (ek - e * std::sin(ek) - mk) / (1.0 - e * std::cos(ek));
    ek -= step;
    if (std::abs(step) < 1e-15) break;
  }
  const double sin_e = std::sin(ek), cos_e = std::cos(ek);
  const double one_minus_ecos = 1.0 - e * cos_e;
  const double root = std::sqrt(1.0 - e * e);
  const double phi = std::atan2(root * sin_e, cos_e - e) + eph.omega_rad;  // argument of latitude
  const double s2 = std::sin(2.0 * phi), c2 = std::cos(2.0 * phi);
  const double u = phi + eph.cus_rad * s2 + eph.cuc_rad * c2;
  const double r = a * one_minus_ecos + eph.crs_m * s2 + eph.crc_m * c2;
  const double i = eph.i0_rad + eph.cis_rad * s2 + eph.cic_rad * c2 + eph.idot_radps * tk;
  const double node_rate = eph.omega_dot_radps - kGpsEarthRate;
  const double node = eph.omega0_rad + node_rate * tk - kGpsEarthRate * eph.toe.seconds_of_week();

  // Rates: dE/dt, d(phi)/dt, then the corrected u, r, i.
  const double e_dot = n / one_minus_ecos;
  const double phi_dot = e_dot * root / one_minus_ecos;
  const double u_dot = phi_dot * (1.0 + 2.0 * (eph.cus_rad * c2 - eph.cuc_rad * s2));
  const double r_dot = a * e * sin_e * e_dot + 2.0 * phi_dot * (eph.crs_m * c2 - eph.crc_m * s2);
  const double i_dot = eph.idot_radps + 2.0 * phi_dot * (eph.cis_rad * c2 - eph.cic_rad * s2);

  const double cu = std::cos(u), su = std::sin(u), ci = std::cos(i), si = std::sin(i);
  const double cn = std::cos(node), sn = std::sin(node);
  const double xp = r * cu, yp = r * su;  // in the orbital plane
  const double xp_dot = r_dot * cu - r * u_dot * su;
  const double yp_dot = r_dot * su + r * u_dot * cu;

  GpsSatelliteState s;
  s.r_ecef_m = {xp * cn - yp * ci * sn, xp * sn + yp * ci * cn, yp * si};
  s.v_ecef_mps = {xp_dot * cn - yp_dot * ci * sn + yp * si * i_dot * sn - s.r_ecef_m.y() * node_rate,
                  xp_dot * sn + yp_dot * ci * cn - yp * si * i_dot * cn + s.r_ecef_m.x() * node_rate,
                  yp_dot * si + yp * ci * i_dot};

  // Clock, IS-GPS-200 20.3.3.3.3.1 (dt from t_oc; the relativistic term uses the same E_k).
  const double dt = t.seconds_since(eph.toc);
  const double relativistic = kGpsRelativisticF * e * eph.sqrt_a * sin_e;
  s.clock_bias_s = eph.af0_s + dt * (eph.af1_sps + dt * eph.af2_sps2) + relativistic;
  s.clock_drift_sps = eph.af1_sps + 2.0 * dt * eph.af2_sps2 + kGpsRelativisticF * e * eph.sqrt_a * cos_e * e_dot;
  return s;
}

double l1_clock_bias_s(const BroadcastEphemeris& eph, const GpsSatelliteState& state) {
  return state.clock_bias_s - eph.tgd_s;
}

bool within_fit_interval(const BroadcastEphemeris& eph, core::GpsTime t) {
  return std::abs(t.seconds_since(eph.toe)) <= 0.5 * eph.fit_interval_h * 3600.0;
}

RecordDisagreement disagreement(const BroadcastEphemeris& a, const BroadcastEphemeris& b) {
  const core::GpsTime middle = a.toe + 0.5 * b.toe.seconds_since(a.toe);
  const GpsSatelliteState sa = broadcast_state(a, middle);
  const GpsSatelliteState sb = broadcast_state(b, middle);
  return {(sa.r_ecef_m - sb.r_ecef_m).norm(), kGpsSpeedOfLight * std::abs(sa.clock_bias_s - sb.clock_bias_s)};
}

}  // namespace visors::gnss
