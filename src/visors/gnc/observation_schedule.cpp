#include "visors/gnc/observation_schedule.hpp"

#include <algorithm>
#include <cmath>

#include "visors/astro/j2_secular.hpp"
#include "visors/astro/mean_osculating.hpp"
#include "visors/astro/apparent_sun.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::gnc {

double slew_lead_s(const ScienceSettings& settings, double angle_rad) {
  return (std::abs(angle_rad) + settings.slew_margin_rad) / settings.slew_rate_radps + settings.slew_settle_s;
}

core::Outcome<AlignedTarget> aligned_mean_roe(const astro::KeplerianElements& chief_mean, core::GpsTime t,
                                                              const control::ScienceGeometry& geometry,
                                                              const core::EarthGravityConstants& gravity) {
  const auto chief_osc = astro::osculating_from_mean(chief_mean, gravity);
  if (!chief_osc.ok()) return chief_osc.status();
  const core::StateVector chief = astro::cartesian_from_keplerian(*chief_osc, gravity.mu);
  const Eigen::Vector3d sun_unit = astro::apparent_target_unit_gcrf(t, chief, geometry.target_offset_rad);
  const Eigen::Matrix3d rtn_to_gcrf = core::gcrf_to_rtn_matrix(chief).transpose();
  const Eigen::Vector3d dr = geometry.focal_distance_m * sun_unit + rtn_to_gcrf * geometry.offset_rtn_m;
  const core::StateVector deputy{chief.r + dr, chief.v + geometry.los_rate_mps * sun_unit};
  const auto deputy_osc = astro::cartesian_to_keplerian(deputy.r, deputy.v, gravity.mu);
  if (!deputy_osc.ok()) return deputy_osc.status();
  const auto deputy_mean = astro::mean_from_osculating(*deputy_osc, gravity);
  if (!deputy_mean.ok()) return deputy_mean.status();
  const auto roe = astro::roe_from_keplerian(chief_mean, *deputy_mean);
  if (!roe.ok()) return roe.status();
  return AlignedTarget{*roe, std::asin(std::clamp(sun_unit.dot(chief.r.normalized()), -1.0, 1.0))};
}

core::Outcome<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const control::ScienceGeometry& geometry,
                                                    const core::EarthGravityConstants& gravity) {
  // science_orbit returns the first crossing after its t0; start the search at now + min_lead
  // (the chief propagated there by the secular J2 rates, as the planners do).
  const astro::KeplerianElements chief_from = astro::propagate_mean_j2(chief_mean, settings.min_lead_s, gravity);
  const core::GpsTime from = now + settings.min_lead_s;
  const auto orbit = control::science_orbit(chief_from, from, geometry, gravity);
  if (!orbit.ok()) return orbit.status();
  // Aligned at the middle of the window: the relative acceleration (~n^2 f) then moves the
  // payloads half as far, and changes their velocity half as much, as when aligned at its start.
  const core::GpsTime aligned = from + orbit->t_obs;
  const auto roe = aligned_mean_roe(astro::propagate_mean_j2(chief_from, orbit->t_obs, gravity), aligned,
                                    geometry, gravity);
  if (!roe.ok()) return roe.status();
  ScheduledObservation out;
  out.index = index;
  out.aligned = aligned;
  out.start = aligned - 0.5 * settings.observation_duration_s;
  out.slew_start = out.start - slew_lead_s(settings, roe->sun_elevation_rad);
  out.end = out.start + settings.observation_duration_s;
  out.roe_target = roe->roe_mean;
  return out;
}

core::Outcome<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const core::EarthGravityConstants& gravity) {
  return next_observation(chief_mean, now, index, settings, settings.geometry, gravity);
}

core::Outcome<bool> choose_north_pole(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                     const ScienceSettings& settings, const control::ScienceGeometry& geometry,
                                     const core::EarthGravityConstants& gravity) {
  bool parallel[2] = {false, false};
  for (int pole = 0; pole < 2; ++pole) {
    control::ScienceGeometry candidate = geometry;
    candidate.north = pole == 1;
    const auto next = next_observation(chief_mean, now, 1, settings, candidate, gravity);
    if (!next.ok()) return next.status();
    const auto& roe = next->roe_target;
    parallel[pole] = roe(astro::roe::kDex) * roe(astro::roe::kDix) + roe(astro::roe::kDey) * roe(astro::roe::kDiy) > 0.0;
  }
  if (parallel[0] != parallel[1]) return parallel[1];
  return geometry.north;
}

}  // namespace visors::gnc
