#include "visors/dynamics/force_model.hpp"

#include <cassert>
#include <cmath>

#include "visors/astro/sun_moon.hpp"
#include "visors/core/rtn_frame.hpp"
#include "visors/dynamics/drag.hpp"
#include "visors/dynamics/harris_priester.hpp"
#include "visors/dynamics/nrlmsise00.hpp"
#include "visors/dynamics/solar_radiation_pressure.hpp"
#include "visors/dynamics/third_body.hpp"

namespace visors::dynamics {
namespace {

using core::Error;

Error nested(const std::string& section, const Error& e) {
  return {e.field.empty() ? section : section + "." + e.field, e.message};
}

// An atmosphere's density times a constant factor (DragConfig::density_scale for models without
// a scale of their own).
class ScaledAtmosphere final : public AtmosphereModel {
 public:
  ScaledAtmosphere(std::unique_ptr<AtmosphereModel> model, double scale) : model_(std::move(model)), scale_(scale) {}
  [[nodiscard]] double density(const AtmosphereQuery& query) const override { return scale_ * model_->density(query); }

 private:
  std::unique_ptr<AtmosphereModel> model_;
  double scale_;
};

// NRLMSISE-00 from `coefficients`, or (without them) the Harris-Priester maximum that stands in
// for it, with a warning.
core::Result<std::unique_ptr<AtmosphereModel>> atmosphere_for(const DragConfig& config,
                                                              const std::optional<Nrlmsise00Coefficients>& coefficients,
                                                              std::optional<std::string>& fallback) {
  if (config.atmosphere == AtmosphereKind::kNrlmsise00 && coefficients) {
    if (!(config.density_scale > 0.0) || !std::isfinite(config.density_scale)) {
      return Error{"drag.density_scale", "must be finite and > 0"};
    }
    auto msis = Nrlmsise00Atmosphere::create(*coefficients);
    if (!msis) return nested("drag.nrlmsise00_coefficients", msis.error());
    std::unique_ptr<AtmosphereModel> model = std::make_unique<Nrlmsise00Atmosphere>(std::move(msis).value());
    if (config.density_scale == 1.0) return model;
    return std::unique_ptr<AtmosphereModel>(std::make_unique<ScaledAtmosphere>(std::move(model), config.density_scale));
  }
  if (config.atmosphere == AtmosphereKind::kNrlmsise00 && !fallback) {
    fallback = "drag.atmosphere: NRLMSISE-00 without its coefficient tables; using the Harris-Priester maximum";
  }
  HarrisPriesterSettings settings;
  settings.cosine_exponent = config.cosine_exponent;
  settings.density_scale = config.density_scale;
  settings.bulge = config.atmosphere == AtmosphereKind::kHarrisPriester ? HarrisPriesterBulge::kDiurnal
                                                                        : HarrisPriesterBulge::kApexMaximum;
  auto hp = HarrisPriesterAtmosphere::create(settings);
  if (!hp) return nested("drag", hp.error());
  return std::unique_ptr<AtmosphereModel>(std::make_unique<HarrisPriesterAtmosphere>(std::move(hp).value()));
}

}  // namespace

ForceModel::ForceModel(ForceModel&&) noexcept = default;
ForceModel& ForceModel::operator=(ForceModel&&) noexcept = default;
ForceModel::~ForceModel() = default;

core::Status ForceModel::check_inputs(const ForceModelConfig& config, const SpacecraftProperties& spacecraft) {
  const std::pair<const char*, double> positive[] = {{"spacecraft.mass", spacecraft.mass},
                                                     {"spacecraft.drag_area", spacecraft.drag_area},
                                                     {"spacecraft.cd", spacecraft.cd},
                                                     {"spacecraft.srp_area", spacecraft.srp_area},
                                                     {"spacecraft.cr", spacecraft.cr}};
  for (const auto& [field, value] : positive) {
    if (!(value > 0.0) || !std::isfinite(value)) return core::Status{core::Problem::kOutOfRange, field, "must be a finite number > 0"};
  }
  if (!config.empirical_rtn.allFinite()) return core::Status{core::Problem::kNotFinite, "empirical_rtn"};
  return {};
}

core::Result<ForceModel> ForceModel::create(const ForceModelConfig& config, const SpacecraftProperties& spacecraft,
                                            ForceModelData data) {
  if (const core::Status ok = check_inputs(config, spacecraft); !ok) return ok.error();
  ForceModel model;
  model.config_ = config;
  model.spacecraft_ = spacecraft;

  if (data.gravity_fallback) model.warnings_.push_back(*data.gravity_fallback);
  const GravityField& field = data.gravity_field;
  const int degree = std::min(config.gravity.degree, field.max_degree);
  const int order = std::min(config.gravity.order, degree);
  if (degree < config.gravity.degree) {
    model.warnings_.push_back("gravity.degree: truncated to " + std::to_string(degree) +
                              ", the maximum of the field in use");
  }
  auto gravity = SphericalHarmonicGravity::create(field, degree, order);
  if (!gravity) return nested("gravity", gravity.error());
  model.gm_ = gravity.value().gm();
  model.radius_ = gravity.value().radius();
  model.gravity_.emplace(std::move(gravity).value());

  if (config.drag.enabled) {
    auto atmosphere = atmosphere_for(config.drag, data.nrlmsise00, data.atmosphere_fallback);
    if (!atmosphere) return atmosphere.error();
    model.atmosphere_ = std::move(atmosphere).value();
    model.space_weather_ = std::move(data.space_weather);
    if (data.atmosphere_fallback) model.warnings_.push_back(*data.atmosphere_fallback);
  }
  if (data.space_weather_fallback) model.warnings_.push_back(*data.space_weather_fallback);
  model.eop_table_ = std::move(data.eop);
  if (data.eop_fallback) model.warnings_.push_back(*data.eop_fallback);
  model.earth_frame_ = core::OnboardEarthFrame({}, config.earth_frame.refresh_interval);
  return model;
}

// EOP from the table once per frame refresh (they change by < 1 mas and 1 ms per day); outside
// the table's range the last values are kept, with zero EOP before the first lookup.
void ForceModel::refresh_earth_orientation(core::GpsTime t) {
  if (!eop_table_) return;
  if (eop_epoch_ && std::abs(t.seconds_since(*eop_epoch_)) < config_.earth_frame.refresh_interval) return;
  eop_epoch_ = t;
  auto eop = eop_table_->at(t);
  if (eop) {
    eop_ = eop.value();
    earth_frame_.set_earth_orientation(eop_);
  } else {
    ++eop_misses_;
  }
}

// Space weather is daily, and with NRLMSISE-00 its ap history changes every 3 hours: it is looked
// up again only when t leaves the cached UTC day or 3-hour interval (a day ending in a leap
// second is treated as 86400 s long, which moves one second to the next interval).
void ForceModel::refresh_solar_activity(core::GpsTime t) {
  if (!space_weather_) return;
  if (activity_start_ && t >= *activity_start_ && t.seconds_since(*activity_start_) < activity_period_) return;
  core::CalendarTime start = t.calendar(core::TimeScale::kUtc);
  const int hour = start.hour;
  start.hour = start.minute = start.second = 0;
  start.nanosecond = 0;
  activity_start_ = core::GpsTime::from_calendar(start, core::TimeScale::kUtc).value();
  activity_period_ = 86400.0;
  auto activity = space_weather_->at(t);
  if (!activity) {  // the configured activity for the whole UTC day
    activity_ = config_.drag.activity;
    ++space_weather_misses_;
    return;
  }
  activity_ = activity.value();
  if (config_.drag.atmosphere != AtmosphereKind::kNrlmsise00 || !config_.drag.ap_history) return;
  // The 3-hour ap interval holding t.
  start.hour = hour / 3 * 3;
  activity_start_ = core::GpsTime::from_calendar(start, core::TimeScale::kUtc).value();
  activity_period_ = 10800.0;
  auto ap = space_weather_->ap_history(t);
  if (ap) {
    activity_.ap_history = ap.value();
  } else {
    ++ap_history_misses_;  // the daily-Ap mode for this interval
  }
}

// Everything that depends on time only, computed once per distinct time: RK4's two mid-step
// evaluations (and both spacecraft of a formation sharing a model) reuse it.
void ForceModel::refresh_time_dependent(core::GpsTime t) {
  if (at_time_.t == t) return;
  refresh_earth_orientation(t);
  at_time_.t = t;
  at_time_.gcrf_to_itrf = earth_frame_.gcrf_to_itrf_matrix(t);
  const bool need_sun = config_.sun || config_.srp.enabled || atmosphere_ != nullptr;
  at_time_.sun_gcrf = need_sun ? astro::sun_position_gcrf(t) : Eigen::Vector3d::Zero();
  at_time_.moon_gcrf = config_.moon ? astro::moon_position_gcrf(t) : Eigen::Vector3d::Zero();
}

Eigen::Vector3d ForceModel::acceleration(core::GpsTime t, const core::StateVector& x_gcrf) {
  return acceleration_terms(t, x_gcrf).total();
}

AccelerationTerms ForceModel::acceleration_terms(core::GpsTime t, const core::StateVector& x_gcrf) {
  AccelerationTerms terms;
  refresh_time_dependent(t);
  const Eigen::Matrix3d& gcrf_to_itrf = at_time_.gcrf_to_itrf;
  const Eigen::Vector3d& sun_gcrf = at_time_.sun_gcrf;
  const Eigen::Vector3d r_itrf = gcrf_to_itrf * x_gcrf.r;
  terms.gravity = gcrf_to_itrf.transpose() * gravity_->acceleration(r_itrf);

  if (atmosphere_ != nullptr) {
    refresh_solar_activity(t);
    const AtmosphereQuery query{t, x_gcrf.r, r_itrf, sun_gcrf, space_weather_ ? activity_ : config_.drag.activity};
    terms.density = atmosphere_->density(query);
    const Eigen::Vector3d omega_gcrf =
        gcrf_to_itrf.transpose() * Eigen::Vector3d(0.0, 0.0, core::earth_rotation_rate(eop_));
    terms.drag = drag_acceleration(x_gcrf, terms.density, spacecraft_.cd, spacecraft_.drag_area,
                                   spacecraft_.mass, omega_gcrf);
  }
  if (config_.srp.enabled) {
    switch (config_.srp.shadow) {
      case ShadowModel::kNone: terms.shadow = 1.0; break;
      case ShadowModel::kCylindrical: terms.shadow = cylindrical_shadow(x_gcrf.r, sun_gcrf, radius_); break;
      case ShadowModel::kConical: terms.shadow = conical_shadow(x_gcrf.r, sun_gcrf, radius_); break;
    }
    terms.srp = srp_acceleration(x_gcrf.r, sun_gcrf, terms.shadow, config_.srp.pressure_1au, spacecraft_.cr,
                                 spacecraft_.srp_area, spacecraft_.mass);
  }
  if (config_.sun) terms.sun = third_body_acceleration(x_gcrf.r, sun_gcrf, kGmSun);
  if (config_.moon) terms.moon = third_body_acceleration(x_gcrf.r, at_time_.moon_gcrf, kGmMoon);
  if (!config_.empirical_rtn.isZero()) {
    terms.empirical = core::gcrf_to_rtn_matrix(x_gcrf).transpose() * config_.empirical_rtn;
  }
  return terms;
}

void ForceModel::set_drag_area(double area_m2) {
  assert(area_m2 > 0.0);
  spacecraft_.drag_area = area_m2;
}

void ForceModel::set_empirical_acceleration_rtn(const Eigen::Vector3d& a_rtn) {
  assert(a_rtn.allFinite());
  config_.empirical_rtn = a_rtn;
}

}  // namespace visors::dynamics
