#pragma once
// Observation scheduling (Guffanti et al., AAS 23-149, 2023, sec. 3, science mode): one attempt per
// orbit, where the aligned relative position lies in the TN plane near the pole chosen by guidance
// (control::science_orbit). The slew to the observation attitude is commanded early enough for the
// largest slew the configuration allows at the slew rate, plus settling.

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/status.hpp"
#include "visors/gnc/gnc_config.hpp"

namespace visors::gnc {

struct ScheduledObservation {
  int index = 0;  // 1-based attempt number
  core::GpsTime slew_start, start, end;
  core::GpsTime aligned;  // the middle of the window, where the formation is aligned
  /// Mean ROE of the aligned science orbit at `aligned` [-].
  astro::RelativeOrbitalElements roe_target = astro::RelativeOrbitalElements::Zero();
};

/// The mean ROE (chief_mean at t) whose OSCULATING relative state at t is the aligned one: the
/// deputy f metres from the chief along the target's apparent direction (geometry.target_offset_rad
/// on the solar disc, seen from the chief: astro/apparent_sun.hpp), plus geometry.offset_rtn_m,
/// with an inertial relative velocity along that line only (geometry.los_rate_mps). Built exactly: chief osculating
/// state, deputy state, deputy mean elements, ROE. control::science_orbit's ROE comes from the
/// first-order map at the MEAN chief instead, which misplaces the deputy by the short-period J2
/// terms (centimetres at 40 m, where the requirement is 18 mm).
struct AlignedTarget {
  astro::RelativeOrbitalElements roe_mean = astro::RelativeOrbitalElements::Zero();  // [-]
  double sun_elevation_rad = 0.0;  // the target above the chief's local horizontal plane [rad]
};
core::Outcome<AlignedTarget> aligned_mean_roe(const astro::KeplerianElements& chief_mean, core::GpsTime t,
                                                              const control::ScienceGeometry& geometry,
                                                              const core::EarthGravityConstants& gravity);

/// The first observation opportunity at least settings.min_lead_s after `now`, for the
/// observation `geometry` (the flight component's, whose pole it chose; settings.geometry is not
/// read). chief_mean: the chief's mean elements at `now`. Errors: those of
/// control::science_orbit ("geometry" ...).
core::Outcome<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const control::ScienceGeometry& geometry,
                                                    const core::EarthGravityConstants& gravity);
/// The same with settings.geometry.
core::Outcome<ScheduledObservation> next_observation(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                                    int index, const ScienceSettings& settings,
                                                    const core::EarthGravityConstants& gravity);

/// The pole for the campaign: the one whose science orbit has PARALLEL relative e and i vectors
/// (de . di > 0), like the standby orbit and the science orbit of Guffanti et al., AAS 23-149, 2023,
/// Table 5, so the transfer never has to turn an e/i-separated orbit inside out (the paper's
/// pathological case: antiparallel science vectors against a parallel standby). If both or neither
/// pole qualifies, geometry.north is kept. Returns true for the north pole.
core::Outcome<bool> choose_north_pole(const astro::KeplerianElements& chief_mean, core::GpsTime now,
                                     const ScienceSettings& settings, const control::ScienceGeometry& geometry,
                                     const core::EarthGravityConstants& gravity);

/// Slew plus settling time commanded before an observation whose slew is `angle_rad` [s]:
/// (angle + margin) / rate + settling.
double slew_lead_s(const ScienceSettings& settings, double angle_rad);

}  // namespace visors::gnc
