#pragma once
// What the ground gives each spacecraft's on-board navigation before a run (`visors run` with
// [navigation] mode = "cdgps", and `visors nav`): the filter's settings, the on-board force
// models, the uplinked Earth orientation, the nominal antenna and rangefinder geometry.

#include <string_view>

#include "visors/core/eop.hpp"
#include "visors/core/result.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/gnc/onboard_navigation.hpp"
#include "visors/nav/cdgps_settings.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::sim {

/// The filter's settings: the flight defaults (nav/cdgps_settings.hpp), then the scenario's [nav]
/// table. Nothing comes from the truth receiver ([gnss.receiver]): a flight team sets its
/// filter's weights from its own characterisation, and a study that makes the truth harsher
/// must not silently retune the filter (docs/truth-and-knowledge.md). Errors name the [nav] key.
core::Result<nav::CdgpsSettings> cdgps_settings(const CampaignScenario& scenario);

/// A spacecraft's on-board force model (dynamics::ForceModelConfig::onboard()) with what the flight
/// software is told of its mass, coefficients and areas ([flight]). Errors name the spacecraft.
core::Result<dynamics::ForceModel> onboard_force_model(const FlightKnowledge& knowledge, gnc::Spacecraft craft);

/// The Earth orientation uplinked to the spacecraft: the IERS values at the run's start from
/// [flight] eop_file (zero when it names none, or the file is not found), not the truth's file. Without them the
/// filter's GCRF turns against the truth's by UT1-UTC and polar motion: ~35 m at 500 km in
/// October 2024.
core::Result<core::EarthOrientation> uplinked_earth_orientation(const CampaignScenario& scenario);

/// The settings of a component's on-board navigation: cdgps_settings(), the calibrated antenna
/// and rangefinder geometry and noise of gnc::OnboardNavigationSettings' defaults (not the truth
/// receiver's), the uplinked Earth orientation.
core::Result<gnc::OnboardNavigationSettings> onboard_navigation_settings(const CampaignScenario& scenario);

/// The antenna lever the flight software knows, body frame, from the nominal centre of mass [m]:
/// the reference point plus the calibrated phase-centre offset along body +Z ([flight], the
/// values onboard_navigation_settings() gives). Scores compare the truth's lever with this one,
/// never with the truth receiver's nominal.
Eigen::Vector3d known_antenna_lever_body_m(const FlightKnowledge& told);

/// The on-board navigation of `self` with both spacecraft's on-board force models.
core::Result<gnc::OnboardNavigation> make_onboard_navigation(const CampaignScenario& scenario, gnc::Spacecraft self);

}  // namespace visors::sim
