#include "sim/simulated_spacecraft.hpp"

#include <string>
#include <utility>

#include "sim/flight_config.hpp"
#include "sim/navigation_setup.hpp"
#include "sim/random_stream.hpp"

namespace visors::sim {

namespace {

core::Result<bool> set_up_truth(SimulatedSpacecraft& v, const CampaignScenario& s, const SpacecraftSettings& sc,
                                const std::string& prefix) {
  auto dynamics = make_truth_dynamics(s, sc, prefix);
  if (!dynamics.ok()) return dynamics.error();
  v.truth = std::move(dynamics).value();
  auto propulsion = Propulsion::create(s.propulsion, sc.mass_kg, sc.propellant_kg, RandomStream(s.seed, prefix + ".propulsion"));
  if (!propulsion.ok()) return core::Error{prefix + "." + propulsion.error().field, propulsion.error().message};
  v.propulsion.emplace(std::move(propulsion).value());
  // The commanded attitude slews at the ADCS's own rate ([attitude]), not the rate the flight
  // software plans with (gnc.science.slew_rate_radps); settling is not part of the truth attitude.
  AttitudeSettings attitude_settings;
  attitude_settings.slew_rate_radps = s.adcs.slew_rate_radps;
  auto attitude = AttitudeProfile::create(attitude_settings);
  if (!attitude.ok()) return core::Error{"attitude.slew_rate_deg_s", attitude.error().message};
  v.attitude.emplace(std::move(attitude).value());
  auto adcs = AdcsModel::create(s.adcs, RandomStream(s.seed, prefix + ".adcs"));
  if (!adcs.ok()) return core::Error{"attitude." + adcs.error().field, adcs.error().message};
  v.adcs.emplace(std::move(adcs).value());
  auto clock = HostClock::create(s.host_clock, RandomStream(s.seed, prefix + ".clock"));
  if (!clock.ok()) return core::Error{"clock." + clock.error().field, clock.error().message};
  v.clock.emplace(std::move(clock).value());
  RandomStream geometry_rng(s.seed, prefix + ".geometry");
  v.geometry.emplace(SpacecraftGeometry::draw(s.geometry, geometry_rng));
  return true;
}

core::Result<bool> set_up_receiver(SimulatedSpacecraft& v, const CampaignScenario& s, const GpsWorld& gps,
                                   const std::string& prefix) {
  GpsReceiverSettings settings = s.gnss.receiver;
  settings.klobuchar = gps.nav.ionosphere.value_or(gnss::KlobucharCoefficients{});
  settings.epoch_interval_s = s.step_s;  // clock_step_sigma_m is per epoch
  settings.phase_center_error_body_m = v.geometry->phase_center_error_body_m();
  auto receiver = GpsReceiver::create(settings, RandomStream(s.seed, prefix + ".gps"));
  if (!receiver.ok()) return core::Error{"gnss.receiver." + receiver.error().field, receiver.error().message};
  v.receiver.emplace(std::move(receiver).value());
  return true;
}

core::Result<bool> set_up_avionics(SimulatedSpacecraft& v, const CampaignScenario& s, bool active, const std::string& prefix,
                                   const GpsWorld* gps) {
  const gnc::GncConfig config = flight_gnc_config(s, v.id, active);
  std::optional<gnc::OnboardNavigation> onboard;
  if (gps != nullptr) {
    if (auto ok = set_up_receiver(v, s, *gps, prefix); !ok) return ok.error();
    auto made = make_onboard_navigation(s, v.id);
    if (!made.ok()) return made.error();
    onboard.emplace(std::move(made).value());
  }
  auto component = gnc::RecordInterface::create(config, std::move(onboard));
  if (!component.ok()) return core::Error{"gnc." + component.error().field, component.error().message};
  v.gnc.emplace(std::move(component).value());
  v.navigation.emplace(s.navigation, RandomStream(s.seed, prefix + ".navigation"));
  CrosslinkSettings link;
  link.delay_s = s.crosslink_delay_s;
  link.drop_probability = s.crosslink_drop_probability;
  auto inbox = Crosslink<gnc::OutputRecords::Record>::create(link, RandomStream(s.seed, prefix + ".crosslink"));
  if (!inbox.ok()) return core::Error{"crosslink." + inbox.error().field, inbox.error().message};
  v.inbox.emplace(std::move(inbox).value());
  return true;
}

}  // namespace

core::Result<bool> set_up_spacecraft(SimulatedSpacecraft& v, const CampaignScenario& scenario,
                                     const SpacecraftSettings& nominal, bool active, const core::StateVector& x0_gcrf,
                                     const GpsWorld* gps) {
  const std::string prefix(v.name);
  v.x_gcrf = x0_gcrf;
  RandomStream ballistics(scenario.seed, prefix + ".ballistics");
  v.true_spacecraft = draw_true_spacecraft(nominal, ballistics);
  if (auto ok = set_up_truth(v, scenario, v.true_spacecraft, prefix); !ok) return ok.error();
  return set_up_avionics(v, scenario, active, prefix, gps);
}

}  // namespace visors::sim
