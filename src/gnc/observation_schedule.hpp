#pragma once
// Observation scheduling (mission paper, science mode): one attempt per orbit, where the aligned
// relative position lies in the TN plane near the pole chosen by guidance
// (control::science_orbit). The slew to the observation attitude is commanded early enough for
// the largest slew the configuration allows at the slew rate, plus settling.

#include "astro/keplerian_elements.hpp"
#include "astro/relative_orbital_elements.hpp"
#include "core/constants.hpp"
#include "core/gps_time.hpp"
#include "core/status.hpp"
#include "gnc/gnc_config.hpp"

namespace visors::gnc {

struct ScheduledObservation {
  int index = 0;  // 1-based attempt number
  core::GpsTime slew_start, start, end;
  /// Mean ROE of the aligned science orbit at `start` [-].
  astro::RelativeOrbitalElements roe_target = astro::RelativeOrbitalElements::Zero();
};

/// The first observation opportunity at least settings.min_lead_s after `now`. chief_mean: the
/// chief's mean elements at `now`. Errors: those of control::science_orbit ("geometry" ...).
core::Result<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const core::EarthGravityConstants& gravity);

/// Slew plus settling time commanded before each observation [s].
double slew_lead_s(const ScienceSettings& settings);

}  // namespace visors::gnc
