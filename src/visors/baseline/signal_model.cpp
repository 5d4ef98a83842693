#include "visors/baseline/signal_model.hpp"

#include <algorithm>
#include <cmath>

#include "visors/core/constants.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/gps_constants.hpp"
#include "visors/gnss/troposphere.hpp"

namespace visors::baseline {
namespace {

constexpr double kC = gnss::kGpsSpeedOfLight;

// The satellite position at transmission, in the Earth-fixed frame of the reception instant:
// rotated by omega_e tau about z, tau iterated on the geometric range (3 iterations: tau changes
// by < 1 ns after the second).
Eigen::Vector3d position_at_reception_frame(const Eigen::Vector3d& r_sat_tx, const Eigen::Vector3d& r_rx) {
  Eigen::Vector3d r = r_sat_tx;
  for (int i = 0; i < 3; ++i) {
    const double theta = gnss::kGpsEarthRate * (r - r_rx).norm() / kC;
    const double c = std::cos(theta), s = std::sin(theta);
    r = {c * r_sat_tx.x() + s * r_sat_tx.y(), -s * r_sat_tx.x() + c * r_sat_tx.y(), r_sat_tx.z()};
  }
  return r;
}

void add_atmosphere(const std::optional<gnss::KlobucharCoefficients>& ionosphere, const ReceiverSite& site,
                    core::GpsTime t_rx, SatelliteSignal& s) {
  if (s.elevation_rad <= 0.0) return;
  if (ionosphere) {
    const gnss::KlobucharGeometry g{site.geodetic.latitude, site.geodetic.longitude, s.azimuth_rad, s.elevation_rad};
    const auto delay = gnss::klobuchar_delay_m(*ionosphere, g, t_rx);
    if (delay) s.ionosphere_l1_m = delay.value();
  }
  const auto tropo = gnss::saastamoinen_delay_m(site.geodetic.latitude, site.geodetic.height, s.elevation_rad, {}, t_rx);
  if (tropo) s.troposphere_m = tropo.value();
}

}  // namespace

ReceiverSite make_site(const Eigen::Vector3d& r_ecef_m) {
  ReceiverSite site;
  site.r_ecef_m = r_ecef_m;
  site.geodetic = core::geodetic_from_itrf(r_ecef_m);
  site.enu_from_ecef = core::enu_from_itrf_rotation(site.geodetic);
  return site;
}

std::optional<SatelliteSignal> model_signal(const gnss::EphemerisSet& ephemerides,
                                            const std::optional<gnss::KlobucharCoefficients>& ionosphere, int prn,
                                            core::GpsTime t_rx, double pseudorange_m, const ReceiverSite& site) {
  core::GpsTime t_tx = t_rx - pseudorange_m / kC;
  const gnss::BroadcastEphemeris* eph = ephemerides.select(prn, t_tx);
  if (eph == nullptr) return std::nullopt;
  // The satellite clock offset at t_tx shifts the transmission time (one correction suffices:
  // the offset changes by < 1e-11 s over the ~1 ms correction).
  t_tx = t_tx - gnss::broadcast_state(*eph, t_tx).clock_bias_s;
  const gnss::GpsSatelliteState state = gnss::broadcast_state(*eph, t_tx);
  SatelliteSignal s;
  const Eigen::Vector3d r_sat = position_at_reception_frame(state.r_ecef_m, site.r_ecef_m);
  const Eigen::Vector3d d = r_sat - site.r_ecef_m;
  s.range_m = d.norm();
  s.los_ecef = d / s.range_m;
  const Eigen::Vector3d enu = site.enu_from_ecef * s.los_ecef;
  s.elevation_rad = std::asin(std::clamp(enu.z(), -1.0, 1.0));
  s.azimuth_rad = std::atan2(enu.x(), enu.y());
  if (s.azimuth_rad < 0.0) s.azimuth_rad += core::kTwoPi;
  s.satellite_clock_m = kC * state.clock_bias_s;
  add_atmosphere(ionosphere, site, t_rx, s);
  return s;
}

}  // namespace visors::baseline
