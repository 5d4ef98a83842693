#pragma once
// What the ground gives each spacecraft's on-board navigation before a run (`visors run` with
// [navigation] mode = "cdgps", and `visors nav`): the filter's settings, the on-board force
// models, the uplinked Earth orientation, the nominal antenna and rangefinder geometry.

#include <string_view>

#include "core/eop.hpp"
#include "core/status.hpp"
#include "dynamics/force_model.hpp"
#include "gnc/onboard_navigation.hpp"
#include "nav/cdgps_settings.hpp"
#include "sim/campaign_scenario.hpp"

namespace visors::sim {

/// The filter's settings: the defaults, then the receiver's specification, then the scenario's
/// [nav] table. The receiver's noise and multipath ([gnss.receiver]) are known on board
/// (characterised on the ground): a single difference has sqrt(2) of each receiver's phase noise
/// and multipath, the SD code at least sqrt(2) of its code noise and multipath, GRAPHIC half the
/// code multipath on top of the default's broadcast-error allowance (multipath is correlated
/// over multipath_tau_s: a white sigma of the same size is the filter's approximation).
/// Errors name the [nav] key.
core::Result<nav::CdgpsSettings> cdgps_settings(const CampaignScenario& scenario);

/// A spacecraft's on-board force model (dynamics::ForceModelConfig::onboard(), its mass and
/// areas). Errors name `name` ("dsc", "osc").
core::Result<dynamics::ForceModel> onboard_force_model(const SpacecraftSettings& spacecraft, std::string_view name);

/// The Earth orientation uplinked to the spacecraft: the IERS values at the run's start from the
/// scenario's EOP file (zero when it names none, or the file is not found). Without them the
/// filter's GCRF turns against the truth's by UT1-UTC and polar motion: ~35 m at 500 km in
/// October 2024.
core::Result<core::EarthOrientation> uplinked_earth_orientation(const CampaignScenario& scenario);

/// The settings of a component's on-board navigation: cdgps_settings(), the nominal antenna
/// ([gnss.receiver] antenna_body_m and phase_center_offset_m from the nominal centre of mass),
/// the rangefinder's nominal lever arms and [gnss.lrf] sigma_m, the uplinked Earth orientation.
core::Result<gnc::OnboardNavigationSettings> onboard_navigation_settings(const CampaignScenario& scenario);

/// The on-board navigation of `self` with both spacecraft's on-board force models.
core::Result<gnc::OnboardNavigation> make_onboard_navigation(const CampaignScenario& scenario, gnc::Spacecraft self);

}  // namespace visors::sim
