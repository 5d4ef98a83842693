#pragma once
// The orbit force model of one spacecraft: spherical-harmonic gravity in the Earth-fixed frame,
// drag in a co-rotating atmosphere, solar radiation pressure with shadow, Sun and Moon as point
// masses and an empirical RTN acceleration, summed in GCRF. Built once from a ForceModelConfig and
// the data its files hold, read beforehand (on the ground: dynamics/files/force_model_files.hpp);
// evaluation allocates nothing.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/status.hpp"
#include "visors/dynamics/atmosphere.hpp"
#include "visors/dynamics/force_model_config.hpp"
#include "visors/dynamics/gravity_field.hpp"
#include "visors/dynamics/nrlmsise00_coefficients.hpp"
#include "visors/dynamics/space_weather.hpp"
#include "visors/dynamics/spherical_harmonic_gravity.hpp"

namespace visors::dynamics {

/// Each term of the acceleration, GCRF [m/s^2]; `gravity` includes the central term.
struct AccelerationTerms {
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();
  Eigen::Vector3d drag = Eigen::Vector3d::Zero();
  Eigen::Vector3d srp = Eigen::Vector3d::Zero();
  Eigen::Vector3d sun = Eigen::Vector3d::Zero();
  Eigen::Vector3d moon = Eigen::Vector3d::Zero();
  Eigen::Vector3d empirical = Eigen::Vector3d::Zero();
  double density = 0.0;  // [kg/m^3]
  double shadow = 1.0;   // illumination factor nu [-]

  [[nodiscard]] Eigen::Vector3d total() const { return gravity + drag + srp + sun + moon + empirical; }
};

/// What a force model is built from besides its configuration: the data of the files the
/// configuration names, already read, and the fallbacks taken for files that were missing (each
/// the text of a warning).
struct ForceModelData {
  /// The field of gravity.model, or embedded_gravity_field().
  GravityField gravity_field;
  /// The table of drag.space_weather, used when drag is enabled; nullopt: the constant
  /// drag.activity.
  std::optional<SpaceWeatherTable> space_weather;
  /// The table of earth_frame.eop; nullopt: zero polar motion and UT1-UTC.
  std::optional<core::EopTable> eop;
  /// The tables of drag.nrlmsise00_coefficients, used when drag.atmosphere is kNrlmsise00;
  /// nullopt: Harris-Priester maximum instead (with atmosphere_fallback's warning).
  std::optional<Nrlmsise00Coefficients> nrlmsise00;
  std::optional<std::string> gravity_fallback;
  std::optional<std::string> atmosphere_fallback;
  std::optional<std::string> space_weather_fallback;
  std::optional<std::string> eop_fallback;
};

class ForceModel {
 public:
  /// The checks of `spacecraft` and `config.empirical_rtn` that create() makes first; an error
  /// names the field. Loaders run them before reading any file.
  static core::Status check_inputs(const ForceModelConfig& config, const SpacecraftProperties& spacecraft);

  /// The model of `config` with `data` (no file is read); an error names the configuration
  /// field. warnings() holds data's fallbacks in the order gravity, degree truncation (when
  /// gravity.degree exceeds the field's), atmosphere (NRLMSISE-00 asked for without its
  /// coefficients: Harris-Priester maximum), space weather, EOP.
  static core::Result<ForceModel> create(const ForceModelConfig& config, const SpacecraftProperties& spacecraft,
                                         ForceModelData data);

  ForceModel(ForceModel&&) noexcept;
  ForceModel& operator=(ForceModel&&) noexcept;
  ~ForceModel();

  /// Total acceleration, GCRF [m/s^2]. Not const: caches (frame, gravity workspace).
  Eigen::Vector3d acceleration(core::GpsTime t, const core::StateVector& x_gcrf);
  /// The same split by term (for reports and the differential-acceleration analysis).
  AccelerationTerms acceleration_terms(core::GpsTime t, const core::StateVector& x_gcrf);

  /// Attitude-dependent cross-section [m^2]; must be > 0 (asserted, validated by callers).
  void set_drag_area(double area_m2);
  void set_empirical_acceleration_rtn(const Eigen::Vector3d& a_rtn);

  [[nodiscard]] const ForceModelConfig& config() const { return config_; }
  [[nodiscard]] const SpacecraftProperties& spacecraft() const { return spacecraft_; }
  /// GM and reference radius of the loaded gravity field.
  [[nodiscard]] double gm() const { return gm_; }
  [[nodiscard]] double earth_radius() const { return radius_; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
  /// UTC days outside the space-weather table (the configured constant activity was used),
  /// 3-hour intervals whose NRLMSISE-00 ap history reaches before the table's start (the day's
  /// activity in the daily-Ap mode was used) and EOP lookups outside the EOP table (the last
  /// values were kept).
  [[nodiscard]] std::int64_t space_weather_misses() const { return space_weather_misses_; }
  [[nodiscard]] std::int64_t ap_history_misses() const { return ap_history_misses_; }
  [[nodiscard]] std::int64_t eop_misses() const { return eop_misses_; }

 private:
  ForceModel() = default;
  void refresh_earth_orientation(core::GpsTime t);
  void refresh_solar_activity(core::GpsTime t);
  void refresh_time_dependent(core::GpsTime t);

  ForceModelConfig config_;
  SpacecraftProperties spacecraft_;
  double gm_ = 0.0;
  double radius_ = 0.0;
  std::optional<SphericalHarmonicGravity> gravity_;
  std::unique_ptr<AtmosphereModel> atmosphere_;
  std::optional<SpaceWeatherTable> space_weather_;
  SolarActivity activity_;  // of the interval [activity_start_, + activity_period_)
  std::optional<core::GpsTime> activity_start_;
  double activity_period_ = 86400.0;  // a UTC day, or 3 h when the atmosphere uses the ap history [s]
  std::optional<core::EopTable> eop_table_;
  std::optional<core::GpsTime> eop_epoch_;
  core::EarthOrientation eop_;
  core::OnboardEarthFrame earth_frame_;
  std::vector<std::string> warnings_;
  struct TimeDependent {
    std::optional<core::GpsTime> t;
    Eigen::Matrix3d gcrf_to_itrf = Eigen::Matrix3d::Identity();
    Eigen::Vector3d sun_gcrf = Eigen::Vector3d::Zero();   // [m]
    Eigen::Vector3d moon_gcrf = Eigen::Vector3d::Zero();  // [m]
  } at_time_;
  std::int64_t space_weather_misses_ = 0;
  std::int64_t ap_history_misses_ = 0;
  std::int64_t eop_misses_ = 0;
};

}  // namespace visors::dynamics
