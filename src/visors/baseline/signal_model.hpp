#pragma once
// The modelled signal path from a GPS satellite to a ground receiver, for differencing: the
// satellite at its transmission time from the broadcast ephemeris, the geometric range with the
// Earth's rotation during the light time (the receiver's Earth-fixed frame at reception), the
// direction, the broadcast (Klobuchar) ionosphere and the Saastamoinen troposphere.
//
// Transmission time (IS-GPS-200 20.3.3.3.3.1; Misra & Enge 2011 sec. 4.3): t_tx = t_rx - P / c,
// where t_rx is the receiver's time tag and P the pseudorange: P / c holds the receiver clock
// offset too, so t_tx is right whatever the receiver clock (the GSI receivers' tags drift by
// +/- 5 ms, ~4 m of satellite motion, which a tag-based transmission time would put into the
// double differences); then the satellite clock offset is removed from it. Light time tau is
// iterated on the geometric range; the satellite position is rotated by omega_e tau about the
// z axis (Sagnac; up to ~30 m of range).

#include <optional>

#include <Eigen/Core>

#include "visors/core/geodetic.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/klobuchar.hpp"

namespace visors::baseline {

struct ReceiverSite {
  Eigen::Vector3d r_ecef_m = Eigen::Vector3d::Zero();
  core::GeodeticPosition geodetic;
  Eigen::Matrix3d enu_from_ecef = Eigen::Matrix3d::Identity();
};

ReceiverSite make_site(const Eigen::Vector3d& r_ecef_m);

struct SatelliteSignal {
  double range_m = 0.0;               // geometric, satellite at transmission to receiver at reception [m]
  Eigen::Vector3d los_ecef = Eigen::Vector3d::Zero();  // unit vector receiver -> satellite
  double elevation_rad = 0.0;
  double azimuth_rad = 0.0;
  double satellite_clock_m = 0.0;     // c x satellite clock offset (with relativity, without T_GD) [m]
  double troposphere_m = 0.0;         // slant delay [m]
  double ionosphere_l1_m = 0.0;       // L1 group delay (= phase advance); L2: times (f1/f2)^2 [m]
};

/// The signal of `prn` received at time tag `t_rx` with pseudorange `pseudorange_m`, or nullopt
/// when no usable ephemeris covers the transmission time. The ionosphere is 0 when `ionosphere`
/// is absent; the troposphere 0 for a satellite below the horizon.
std::optional<SatelliteSignal> model_signal(const gnss::EphemerisSet& ephemerides,
                                            const std::optional<gnss::KlobucharCoefficients>& ionosphere, int prn,
                                            core::GpsTime t_rx, double pseudorange_m, const ReceiverSite& site);

}  // namespace visors::baseline
