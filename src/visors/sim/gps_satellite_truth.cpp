#include "visors/sim/gps_satellite_truth.hpp"

#include <array>
#include <cmath>

#include "visors/gnss/gps_constants.hpp"

namespace visors::sim {

core::Result<bool> BroadcastErrorSettings::validate() const {
  const struct {
    const char* name;
    double value;
  } fields[] = {{"radial_m", radial_m}, {"along_m", along_m}, {"cross_m", cross_m}, {"clock_m", clock_m},
                {"clock_drift_sps", clock_drift_sps}, {"refresh_s", refresh_s}};
  for (const auto& f : fields) {
    if (!(std::isfinite(f.value) && f.value >= 0.0)) return core::Error{f.name, "must be finite and >= 0"};
  }
  if (refresh_s > 0.0 && refresh_s < 600.0) return core::Error{"refresh_s", "must be 0 (one set) or >= 600 s"};
  if (!(refresh_correlation >= 0.0 && refresh_correlation <= 1.0)) {
    return core::Error{"refresh_correlation", "must be in [0, 1]"};
  }
  return true;
}

namespace {

// Eight unit normal draws, one per element error of the file comment: a, e cos w, e sin w, M0,
// i0, Omega0, a_f0, a_f1.
using UnitErrors = std::array<double, 8>;

UnitErrors draw_unit_errors(RandomStream& rng) {
  UnitErrors z{};
  for (double& v : z) v = rng.normal(1.0);
  return z;
}

gnss::BroadcastEphemeris perturbed(const gnss::BroadcastEphemeris& truth, const BroadcastErrorSettings& s,
                                   const UnitErrors& z) {
  gnss::BroadcastEphemeris b = truth;
  const double a = truth.sqrt_a * truth.sqrt_a;
  const double da = z[0] * s.radial_m;
  const double dex = z[1] * (s.radial_m / a);
  const double dey = z[2] * (s.radial_m / a);
  const double dm = z[3] * (s.along_m / a);
  const double di = z[4] * (s.cross_m / a);
  const double dnode = z[5] * (s.cross_m / a) / std::sin(truth.i0_rad);
  b.sqrt_a = std::sqrt(a + da);
  // Keep n = sqrt(mu / A^3) + delta_n: no along-track drift from delta a.
  b.delta_n_radps += std::sqrt(gnss::kGpsMu / (a * a * a)) - std::sqrt(gnss::kGpsMu / std::pow(a + da, 3));
  // Eccentricity vector (e cos w, e sin w) += (dex, dey), with the mean argument of latitude
  // M + w kept, so the along-track error is dm alone.
  const double ex = truth.eccentricity * std::cos(truth.omega_rad) + dex;
  const double ey = truth.eccentricity * std::sin(truth.omega_rad) + dey;
  b.eccentricity = std::hypot(ex, ey);
  b.omega_rad = std::atan2(ey, ex);
  b.m0_rad = truth.m0_rad + (truth.omega_rad - b.omega_rad) + dm;
  b.i0_rad += di;
  b.omega0_rad += dnode;
  b.af0_s += z[6] * (s.clock_m / gnss::kGpsSpeedOfLight);
  b.af1_sps += z[7] * s.clock_drift_sps;
  return b;
}

// The truth record as a data set of reference time `toe` describing the same orbit and clock
// (file comment): every secular term carried by its rate, the harmonic terms unchanged.
gnss::BroadcastEphemeris reexpressed(const gnss::BroadcastEphemeris& truth, core::GpsTime toe, int iode,
                                     double refresh_s) {
  gnss::BroadcastEphemeris b = gnss::propagate_to_epoch(truth, toe);
  const double d = toe.seconds_since(truth.toc);
  b.i0_rad = truth.i0_rad + truth.idot_radps * toe.seconds_since(truth.toe);
  b.idot_radps = truth.idot_radps;
  b.af0_s = truth.af0_s + d * (truth.af1_sps + d * truth.af2_sps2);
  b.af1_sps = truth.af1_sps + 2.0 * d * truth.af2_sps2;
  b.fit_interval_h = 4.0;
  b.iode = iode;
  b.transmission = toe - 0.5 * refresh_s;
  return b;
}

}  // namespace

core::Result<GpsSatelliteTruth> GpsSatelliteTruth::create(const gnss::GpsConstellation& constellation,
                                                          const BroadcastErrorSettings& errors, RandomStream rng,
                                                          double span_s) {
  if (auto valid = errors.validate(); !valid) return valid.error();
  if (!(std::isfinite(span_s) && span_s >= 0.0)) return core::Error{"span_s", "must be finite and >= 0"};
  GpsSatelliteTruth truth;
  std::vector<UnitErrors> z;
  for (const auto& record : constellation.satellites()) {
    z.push_back(draw_unit_errors(rng));
    truth.truth_.push_back(record);
    truth.broadcast_.push_back(perturbed(record, errors, z.back()));
    truth.phase_offset_cycles_.push_back(rng.uniform());
  }
  // Sets k = 1..K with t_oe_k = t0 + k refresh_s, K the last whose use (from t_oe_k - refresh_s / 2)
  // starts within the span.
  const int sets = errors.refresh_s > 0.0 ? static_cast<int>(std::floor(span_s / errors.refresh_s + 0.5)) : 0;
  const double rho = errors.refresh_correlation, innovation = std::sqrt(1.0 - rho * rho);
  for (int k = 1; k <= sets; ++k) {
    for (std::size_t j = 0; j < truth.truth_.size(); ++j) {
      const UnitErrors w = draw_unit_errors(rng);
      for (std::size_t e = 0; e < w.size(); ++e) z[j][e] = rho * z[j][e] + innovation * w[e];
      const gnss::BroadcastEphemeris& record = truth.truth_[j];
      const gnss::BroadcastEphemeris set = reexpressed(record, record.toe + k * errors.refresh_s, k % 256, errors.refresh_s);
      truth.broadcast_.push_back(perturbed(set, errors, z[j]));
    }
  }
  truth.screened_.resize(truth.truth_.size());
  return truth;
}

Eigen::Vector3d GpsSatelliteTruth::screening_position_ecef(std::size_t index, core::GpsTime t) const {
  Screened& s = screened_[index];
  if (s.valid && std::abs(t.seconds_since(s.t)) <= kScreenReuseS) return s.r_ecef_m + s.v_ecef_mps * t.seconds_since(s.t);
  const gnss::GpsSatelliteState state = gnss::broadcast_state(truth_[index], t);
  s = Screened{true, t, state.r_ecef_m, state.v_ecef_mps};
  return s.r_ecef_m;
}

gnss::GpsSatelliteState GpsSatelliteTruth::true_state(std::size_t index, core::GpsTime t) const {
  const gnss::BroadcastEphemeris& record = truth_[index];
  gnss::GpsSatelliteState state = gnss::broadcast_state(record, t);
  state.clock_bias_s = gnss::l1_clock_bias_s(record, state);
  return state;
}

}  // namespace visors::sim
