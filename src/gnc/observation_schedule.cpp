#include "gnc/observation_schedule.hpp"

#include "astro/j2_secular.hpp"

namespace visors::gnc {

double slew_lead_s(const ScienceSettings& settings) {
  return settings.max_slew_angle_rad / settings.slew_rate_rad_s + settings.slew_settle_s;
}

core::Result<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const core::EarthGravityConstants& gravity) {
  // science_orbit returns the first crossing after its t0; start the search at now + min_lead
  // (the chief propagated there by the secular J2 rates, as the planners do).
  const astro::KeplerianElements chief_from = astro::propagate_mean_j2(chief_mean, settings.min_lead_s, gravity);
  const core::GpsTime from = now + settings.min_lead_s;
  const auto orbit = control::science_orbit(chief_from, from, settings.geometry, gravity);
  if (!orbit.ok()) return orbit.error();
  ScheduledObservation out;
  out.index = index;
  out.start = from + orbit->t_obs;
  out.slew_start = out.start - slew_lead_s(settings);
  out.end = out.start + settings.observation_duration_s;
  out.roe_target = orbit->roe;
  return out;
}

}  // namespace visors::gnc
