#include "visors/sim/navigation_setup.hpp"

#include <string>

#include "visors/config/cdgps_settings_toml.hpp"
#include "visors/config/toml_fields.hpp"
#include "visors/core/files/data_path.hpp"
#include "visors/core/files/eop_file.hpp"
#include "visors/dynamics/files/force_model_files.hpp"
#include "visors/sim/flight_config.hpp"

namespace visors::sim {

core::Result<nav::CdgpsSettings> cdgps_settings(const CampaignScenario& s) {
  nav::CdgpsSettings settings;  // the flight team's defaults, never the truth receiver's errors
  if (s.nav_toml.empty()) return settings;
  auto table = config::toml_fields::parse(s.nav_toml);
  if (!table.ok()) return table.error();
  if (auto ok = config::read_cdgps_settings(table.value(), settings); !ok) return ok.error();
  return settings;
}

core::Result<dynamics::ForceModel> onboard_force_model(const FlightKnowledge& knowledge, gnc::Spacecraft craft) {
  const std::string_view name = craft == gnc::Spacecraft::kDsc ? "dsc" : "osc";
  const dynamics::SpacecraftProperties p = flight_spacecraft_properties(knowledge, craft);
  auto model = dynamics::files::load_force_model(dynamics::ForceModelConfig::onboard(), p);
  if (!model.ok()) return core::Error{std::string(name) + " on-board force model", model.error().describe()};
  return std::move(model).value();
}

core::Result<core::EarthOrientation> uplinked_earth_orientation(const CampaignScenario& s) {
  if (s.flight.eop_file.empty()) return core::EarthOrientation{};
  const auto path = core::files::find_data_file(s.flight.eop_file);
  if (!path) return core::EarthOrientation{};
  auto table = core::files::read_eop_file(*path);
  if (!table.ok()) return core::Error{"flight.eop_file", table.error().describe()};
  auto at = table.value().at(s.t0);
  return at.ok() ? at.value() : core::EarthOrientation{};
}

core::Result<gnc::OnboardNavigationSettings> onboard_navigation_settings(const CampaignScenario& s) {
  gnc::OnboardNavigationSettings settings;
  auto filter = cdgps_settings(s);
  if (!filter.ok()) return filter.error();
  settings.filter = filter.value();
  // The antenna, rangefinder and their levers: the flight team's calibrated values ([flight]; the
  // truth's differ by its drawn errors: docs/truth-and-knowledge.md).
  settings.antenna_arp_body_m = s.flight.antenna_arp_body_m;
  settings.antenna_pco_m = s.flight.antenna_pco_m;
  settings.lrf_lever_body_m = s.flight.lrf_lever_body_m;
  settings.lrf_sigma_m = s.flight.lrf_sigma_m;
  settings.lrf_bias_m = s.flight.lrf_bias_m;
  auto eop = uplinked_earth_orientation(s);
  if (!eop.ok()) return eop.error();
  settings.earth_orientation = eop.value();
  return settings;
}

Eigen::Vector3d known_antenna_lever_body_m(const FlightKnowledge& told) {
  return told.antenna_arp_body_m + told.antenna_pco_m * Eigen::Vector3d::UnitZ();
}

core::Result<gnc::OnboardNavigation> make_onboard_navigation(const CampaignScenario& s, gnc::Spacecraft self) {
  auto settings = onboard_navigation_settings(s);
  if (!settings.ok()) return settings.error();
  auto dsc = onboard_force_model(s.flight, gnc::Spacecraft::kDsc);
  if (!dsc.ok()) return dsc.error();
  auto osc = onboard_force_model(s.flight, gnc::Spacecraft::kOsc);
  if (!osc.ok()) return osc.error();
  auto navigation = gnc::OnboardNavigation::create(settings.value(), self, std::move(dsc).value(), std::move(osc).value());
  if (!navigation.ok()) return core::Error{"nav." + navigation.error().field, navigation.error().message};
  return navigation;
}

}  // namespace visors::sim
