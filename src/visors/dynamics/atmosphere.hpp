#pragma once
// Neutral-density interface shared by the on-board and truth atmospheres. Every model answers the
// same query, so the truth world can swap Harris-Priester for NRLMSISE-00 (or any other model
// needing geodetic position, local time and space weather) without touching drag or the
// propagators.

#include <array>
#include <optional>

#include <Eigen/Core>

#include "visors/core/gps_time.hpp"

namespace visors::dynamics {

/// Solar and geomagnetic activity for one instant, in the NRLMSISE-00 convention (Picone et al.
/// 2002; docs/nrlmsise00.md#conventions): f107 is the previous day's observed F10.7, f107a its
/// 81-day centred mean.
struct SolarActivity {
  double f107 = 150.0;   // [sfu] (1e-22 W m^-2 Hz^-1)
  double f107a = 150.0;  // [sfu]
  double ap = 15.0;      // daily planetary index [2 nT]
  /// The NRLMSISE-00 ap array [2 nT], when the 3-hourly history is known: [0] daily Ap, [1] the
  /// 3-hourly ap of the current interval, [2], [3], [4] those 3, 6 and 9 h before, [5] the mean
  /// of the eight from 12 to 33 h before, [6] the mean of the eight from 36 to 57 h before
  /// (SpaceWeatherTable::ap_history). With it NRLMSISE-00 runs in its ap-history mode; models
  /// without a geomagnetic history ignore it.
  std::optional<std::array<double, 7>> ap_history;
};

struct AtmosphereQuery {
  core::GpsTime t;
  Eigen::Vector3d r_gcrf = Eigen::Vector3d::Zero();    // spacecraft position [m]
  Eigen::Vector3d r_itrf = Eigen::Vector3d::Zero();    // same point, Earth-fixed [m]
  Eigen::Vector3d sun_gcrf = Eigen::Vector3d::Zero();  // Sun position [m]
  SolarActivity activity;
};

class AtmosphereModel {
 public:
  virtual ~AtmosphereModel() = default;
  /// Mass density [kg/m^3]; 0 outside the model's altitude range (above it the density is
  /// negligible for drag; below it the orbit has already decayed).
  [[nodiscard]] virtual double density(const AtmosphereQuery& query) const = 0;
};

}  // namespace visors::dynamics
