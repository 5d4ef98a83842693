#pragma once
// A synthetic GPS constellation for navigation tests: 24 satellites in 6 planes of 4 (55 deg,
// A = 26,560 km, e = 0.01), as broadcast ephemerides with t_oe at `toe`, small clock offsets;
// and L1 observations of a receiver computed with the filter's range model (so the tests check
// the filter's algebra, not the model, which has its own tests).

#include <cmath>
#include <random>
#include <vector>

#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/nav/gps_observations.hpp"
#include "visors/nav/gps_range_model.hpp"

namespace visors::test {

inline std::vector<gnss::BroadcastEphemeris> synthetic_constellation(core::GpsTime toe) {
  std::vector<gnss::BroadcastEphemeris> out;
  for (int plane = 0; plane < 6; ++plane) {
    for (int k = 0; k < 4; ++k) {
      gnss::BroadcastEphemeris e;
      e.prn = 1 + 4 * plane + k;
      e.toe = e.toc = e.transmission = toe;
      e.sqrt_a = 5153.7;
      e.eccentricity = 0.01;
      e.i0_rad = 55.0 * M_PI / 180.0;
      e.omega0_rad = std::remainder(plane * M_PI / 3.0, 2.0 * M_PI);  // broadcast angles lie in [-pi, pi]
      e.m0_rad = std::remainder(k * M_PI / 2.0 + plane * M_PI / 12.0, 2.0 * M_PI);
      e.af0_s = 1e-5 * (k - 1.5);
      out.push_back(e);
    }
  }
  return out;
}

/// Code and phase of a zenith-pointing receiver (5 deg mask above the local horizontal) with
/// clock `clock_m`, its phase centre at the antenna geometry plus truth.pco_error_body_m; phase = (geometric range + noise) / lambda + integers[prn] + phase offset.
inline nav::GpsReceiverEpoch synthetic_observations(core::GpsTime t, const nav::ReceiverEstimate& truth,
                                                     const std::vector<gnss::BroadcastEphemeris>& records,
                                                     core::OnboardEarthFrame& frame, const std::vector<double>& integers,
                                                     double phase_offset_cycles, double code_sigma_m, double phase_sigma_m,
                                                     std::mt19937_64& rng, const nav::AntennaGeometry& antenna = {}) {
  std::normal_distribution<double> gauss;
  nav::GpsReceiverEpoch e;
  e.t = t;
  for (const auto& eph : records) {
    const nav::RangePrediction p = nav::predict_range(t, truth, antenna, eph, frame);
    if (p.line_of_sight_gcrf.dot(truth.r_gcrf_m.normalized()) < std::sin(5.0 * M_PI / 180.0)) continue;
    if (e.count == nav::kGpsSlots) break;
    const double geometric = p.range_m + truth.clock_m - p.satellite_clock_m;
    nav::GpsObservation& o = e.observations[static_cast<std::size_t>(e.count++)];
    o.prn = eph.prn;
    o.code_m = geometric + code_sigma_m * gauss(rng);
    o.phase_cycles = (geometric + phase_sigma_m * gauss(rng)) / gnss::kL1WavelengthM +
                     integers[static_cast<std::size_t>(eph.prn)] + phase_offset_cycles;
  }
  return e;
}

}  // namespace visors::test
