#include "visors/nav/cold_start.hpp"

#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::nav {

std::optional<ColdStartSolution> ColdStart::add(const GpsReceiverEpoch& dsc, const GpsReceiverEpoch& osc,
                                                const AntennaGeometry& dsc_antenna, const AntennaGeometry& osc_antenna,
                                                const gnss::EphemerisSource& ephemerides, core::OnboardEarthFrame& frame) {
  if (osc.t != dsc.t) return std::nullopt;
  const GpsReceiverEpoch* epochs[2] = {&dsc, &osc};
  const AntennaGeometry* antennas[2] = {&dsc_antenna, &osc_antenna};
  PointSolution now[2];
  for (int k = 0; k < 2; ++k) {
    now[k] = solve_point_position(*epochs[k], ephemerides, frame, Eigen::Vector3d::Zero());
    if (!now[k].ok) return std::nullopt;
  }
  const core::GpsTime t = dsc.t;
  if (!have_first_ || t.seconds_since(t_first_) > 3.0 * kGapS || t < t_first_) {
    have_first_ = true;
    t_first_ = t;
    first_[0] = now[0];
    first_[1] = now[1];
    return std::nullopt;
  }
  const double dt = t.seconds_since(t_first_);
  if (dt < kGapS) return std::nullopt;
  core::StateVector x[2];
  const double mu = core::EarthGravityConstants{}.mu;
  for (int k = 0; k < 2; ++k) {
    const Eigen::Vector3d r = now[k].r_gcrf_m;
    const Eigen::Vector3d gravity = -mu / std::pow(r.norm(), 3) * r;
    x[k].v = (r - first_[k].r_gcrf_m) / dt + 0.5 * dt * gravity;
    const AntennaGeometry& a = *antennas[k];
    x[k].r = r - a.body_to_gcrf * (a.arp_body_m + a.pco_body_m);
  }
  have_first_ = false;
  return ColdStartSolution{t, x[0], x[1], now[0].clock_m, now[1].clock_m};
}

}  // namespace visors::nav
