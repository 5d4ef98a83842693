#pragma once
// Single-point positioning from one receiver's L1 C/A pseudoranges: the cold start of the
// navigation filter (its first position and clock; two solutions some seconds apart give the
// first velocity). Gauss-Newton least squares on code = rho + c dt - c dt_sat with the filter's
// own range model (nav/gps_range_model.hpp; the receiver's velocity taken as zero within the
// light-time and reception-instant terms: at 1 us of clock offset that is 8 mm), equal weights,
// no ionosphere model (the topside delay of a 500 km orbit, ~1-3 m, goes into the solution).
// Fails (ok = false, reason) with fewer than 5 satellites (4 unknowns plus one to see a blunder),
// when it does not converge, or when the residuals' RMS exceeds max_rms_m.

#include <Eigen/Core>

#include "visors/core/earth_frames.hpp"
#include "visors/gnss/ephemeris_source.hpp"
#include "visors/nav/gps_observations.hpp"

namespace visors::nav {

struct PointSolution {
  bool ok = false;
  const char* reason = "";  // "too_few_satellites", "not_converged", "residuals"
  Eigen::Vector3d r_gcrf_m = Eigen::Vector3d::Zero();  // antenna phase centre at the time tag
  double clock_m = 0.0;     // receiver clock offset x c [m]
  int satellites = 0;
  double rms_m = 0.0;       // RMS of the post-fit residuals [m]
};

/// From `guess` (GCRF [m]; the Earth's centre works: GPS geometry converges from there).
PointSolution solve_point_position(const GpsReceiverEpoch& epoch, const gnss::EphemerisSource& ephemerides,
                                   core::OnboardEarthFrame& frame, const Eigen::Vector3d& guess_gcrf_m,
                                   double max_rms_m = 30.0);

}  // namespace visors::nav
