#include "visors/baseline/single_difference.hpp"

#include <algorithm>
#include <cmath>

#include "visors/gnss/gps_constants.hpp"

namespace visors::baseline {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// (f1/f2)^2: the first-order ionosphere scales with 1/f^2.
constexpr double kL2IonosphereFactor =
    (gnss::kL1FrequencyHz / gnss::kL2FrequencyHz) * (gnss::kL1FrequencyHz / gnss::kL2FrequencyHz);

double phase_variance(const BaselineSettings& s, double elevation) {
  const double sin_el = std::max(std::sin(elevation), 0.05);  // 3 deg floor: the model's pole
  return s.phase_sigma_m * s.phase_sigma_m +
         s.phase_sigma_elevation_m * s.phase_sigma_elevation_m / (sin_el * sin_el);
}

}  // namespace

double wavelength_m(int frequency) { return frequency == 0 ? gnss::kL1WavelengthM : gnss::kL2WavelengthM; }

SingleDifference single_difference(const SatelliteObservables& rover, const SatelliteSignal& rover_signal,
                                   const SatelliteObservables& base, const SatelliteSignal& base_signal,
                                   const BaselineSettings& settings) {
  SingleDifference sd;
  sd.prn = rover.prn;
  sd.elevation_rad = rover_signal.elevation_rad;
  sd.azimuth_rad = rover_signal.azimuth_rad;
  sd.los_rover = rover_signal.los_ecef;
  const double geometry = (rover_signal.range_m - base_signal.range_m) -
                          (rover_signal.satellite_clock_m - base_signal.satellite_clock_m) +
                          (rover_signal.troposphere_m - base_signal.troposphere_m);
  const double iono_l1 = rover_signal.ionosphere_l1_m - base_signal.ionosphere_l1_m;
  const double variance = phase_variance(settings, rover_signal.elevation_rad) +
                          phase_variance(settings, base_signal.elevation_rad);
  const int used = settings.frequencies == FrequencySet::kL1 ? 1 : 2;
  for (int f = 0; f < kFrequencies; ++f) {
    const auto fi = static_cast<std::size_t>(f);
    const double iono = f == 0 ? iono_l1 : iono_l1 * kL2IonosphereFactor;
    const double lambda = wavelength_m(f);
    sd.phase_m[fi] = f < used ? lambda * (rover.phase_cyc[fi] - base.phase_cyc[fi]) - (geometry - iono) : kNaN;
    sd.code_m[fi] = f < used ? (rover.code_m[fi] - base.code_m[fi]) - (geometry + iono) : kNaN;
    sd.phase_var_m2[fi] = variance;
    sd.code_var_m2[fi] = variance * settings.code_to_phase_sigma * settings.code_to_phase_sigma;
  }
  return sd;
}

}  // namespace visors::baseline
