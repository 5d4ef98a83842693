#include "visors/sim/flight_config.hpp"

#include <string>

#include "visors/gnc/files/flight_config_json.hpp"
#include "visors/sim/navigation_setup.hpp"

namespace visors::sim {
namespace {

// What `craft`'s component is created with.
core::Result<gnc::files::ComponentSetup> component_setup(const CampaignScenario& s, gnc::Spacecraft craft) {
  const std::string_view name = craft == gnc::Spacecraft::kDsc ? "dsc" : "osc";
  gnc::files::ComponentSetup setup{.gnc = flight_gnc_config(s, craft, s.active == name), .navigation = std::nullopt};
  if (s.navigation_mode == NavigationMode::kCdgps) {
    auto navigation = onboard_navigation_settings(s);
    if (!navigation.ok()) return navigation.error();
    gnc::files::NavigationSetup n{.settings = navigation.value(),
                                  .force_model = dynamics::ForceModelConfig::onboard(),
                                  .dsc = flight_spacecraft_properties(s.flight, gnc::Spacecraft::kDsc),
                                  .osc = flight_spacecraft_properties(s.flight, gnc::Spacecraft::kOsc)};
    n.settings.filter.local = craft == gnc::Spacecraft::kDsc ? nav::Craft::kDsc : nav::Craft::kOsc;  // as create() sets it
    setup.navigation = std::move(n);
  }
  return setup;
}

}  // namespace

gnc::GncConfig flight_gnc_config(const CampaignScenario& s, gnc::Spacecraft craft, bool active) {
  gnc::GncConfig config = s.gnc;
  config.self = craft;
  config.active = active;
  config.mass_kg = craft == gnc::Spacecraft::kDsc ? s.flight.dsc_mass_kg : s.flight.osc_mass_kg;  // what it is told
  return config;
}

dynamics::SpacecraftProperties flight_spacecraft_properties(const FlightKnowledge& k, gnc::Spacecraft craft) {
  dynamics::SpacecraftProperties p;
  p.mass = craft == gnc::Spacecraft::kDsc ? k.dsc_mass_kg : k.osc_mass_kg;
  p.cd = k.cd;
  p.cr = k.cr;
  p.drag_area = k.drag_area_m2;
  p.srp_area = k.srp_area_m2;
  return p;
}

core::Result<nlohmann::json> flight_config_json(const CampaignScenario& s) {
  nlohmann::json out;
  for (const gnc::Spacecraft craft : {gnc::Spacecraft::kDsc, gnc::Spacecraft::kOsc}) {
    auto setup = component_setup(s, craft);
    if (!setup.ok()) return setup.error();
    out[craft == gnc::Spacecraft::kDsc ? "dsc" : "osc"] = gnc::files::to_json(setup.value());
  }
  return out;
}

}  // namespace visors::sim
