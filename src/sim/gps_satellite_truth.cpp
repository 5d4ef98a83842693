#include "sim/gps_satellite_truth.hpp"

#include <cmath>

#include "gnss/gps_constants.hpp"

namespace visors::sim {

core::Result<bool> BroadcastErrorSettings::validate() const {
  const struct {
    const char* name;
    double value;
  } fields[] = {{"radial_m", radial_m}, {"along_m", along_m}, {"cross_m", cross_m}, {"clock_m", clock_m},
                {"clock_drift_sps", clock_drift_sps}};
  for (const auto& f : fields) {
    if (!(std::isfinite(f.value) && f.value >= 0.0)) return core::Error{f.name, "must be finite and >= 0"};
  }
  return true;
}

namespace {

gnss::BroadcastEphemeris perturbed(const gnss::BroadcastEphemeris& truth, const BroadcastErrorSettings& s,
                                   RandomStream& rng) {
  gnss::BroadcastEphemeris b = truth;
  const double a = truth.sqrt_a * truth.sqrt_a;
  const double da = rng.normal(s.radial_m);
  const double dex = rng.normal(s.radial_m / a);
  const double dey = rng.normal(s.radial_m / a);
  const double dm = rng.normal(s.along_m / a);
  const double di = rng.normal(s.cross_m / a);
  const double dnode = rng.normal(s.cross_m / a) / std::sin(truth.i0_rad);
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
  b.af0_s += rng.normal(s.clock_m / gnss::kGpsSpeedOfLight);
  b.af1_sps += rng.normal(s.clock_drift_sps);
  return b;
}

}  // namespace

core::Result<GpsSatelliteTruth> GpsSatelliteTruth::create(const gnss::GpsConstellation& constellation,
                                                          const BroadcastErrorSettings& errors, RandomStream rng) {
  if (auto valid = errors.validate(); !valid) return valid.error();
  GpsSatelliteTruth truth;
  for (const auto& record : constellation.satellites()) {
    truth.truth_.push_back(record);
    truth.broadcast_.push_back(perturbed(record, errors, rng));
    truth.phase_offset_cycles_.push_back(rng.uniform());
  }
  return truth;
}

gnss::GpsSatelliteState GpsSatelliteTruth::true_state(std::size_t index, core::GpsTime t) const {
  const gnss::BroadcastEphemeris& record = truth_[index];
  gnss::GpsSatelliteState state = gnss::broadcast_state(record, t);
  state.clock_bias_s = gnss::l1_clock_bias_s(record, state);
  return state;
}

}  // namespace visors::sim
