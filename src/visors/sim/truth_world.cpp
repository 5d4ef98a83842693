#include "visors/sim/truth_world.hpp"

#include <string>
#include <utility>

#include "visors/core/rtn_frame.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {
namespace {

// One spacecraft's truth models (`x.id`, `x.name` set), its true ballistics drawn from `nominal`.
core::Result<bool> set_up(TruthSpacecraft& x, const CampaignScenario& s, const SpacecraftSettings& nominal,
                          const core::StateVector& x0_gcrf) {
  const std::string prefix(x.name);
  x.x_gcrf = x0_gcrf;
  RandomStream ballistics(s.seed, prefix + ".ballistics");
  x.true_spacecraft = draw_true_spacecraft(nominal, ballistics);
  const SpacecraftSettings& sc = x.true_spacecraft;
  auto dynamics = make_truth_dynamics(s, sc, prefix);
  if (!dynamics.ok()) return dynamics.error();
  x.dynamics = std::move(dynamics).value();
  auto propulsion = Propulsion::create(s.propulsion, sc.mass_kg, sc.propellant_kg, RandomStream(s.seed, prefix + ".propulsion"));
  if (!propulsion.ok()) return core::Error{prefix + "." + propulsion.error().field, propulsion.error().message};
  x.propulsion.emplace(std::move(propulsion).value());
  // The commanded attitude slews at the ADCS's own rate ([attitude]), not the rate the flight
  // software plans with (gnc.science.slew_rate_radps); settling is not part of the truth attitude.
  AttitudeSettings attitude_settings;
  attitude_settings.slew_rate_radps = s.adcs.slew_rate_radps;
  attitude_settings.calibration = s.calibration_yaw;
  auto attitude = AttitudeProfile::create(attitude_settings);
  if (!attitude.ok()) return core::Error{"attitude.slew_rate_deg_s", attitude.error().message};
  x.attitude.emplace(std::move(attitude).value());
  auto adcs = AdcsModel::create(s.adcs, RandomStream(s.seed, prefix + ".adcs"));
  if (!adcs.ok()) return core::Error{"attitude." + adcs.error().field, adcs.error().message};
  x.adcs.emplace(std::move(adcs).value());
  RandomStream geometry_rng(s.seed, prefix + ".geometry");
  x.geometry.emplace(SpacecraftGeometry::draw(s.geometry, geometry_rng));
  return true;
}

}  // namespace

core::Result<TruthWorld> TruthWorld::create(const CampaignScenario& scenario, const core::StateVector& dsc0_gcrf,
                                            const core::StateVector& osc0_gcrf) {
  TruthWorld world(scenario);
  world.craft_[0].id = gnc::Spacecraft::kDsc;
  world.craft_[0].name = "dsc";
  world.craft_[1].id = gnc::Spacecraft::kOsc;
  world.craft_[1].name = "osc";
  if (auto ok = set_up(world.craft_[0], scenario, scenario.dsc, dsc0_gcrf); !ok) return ok.error();
  if (auto ok = set_up(world.craft_[1], scenario, scenario.osc, osc0_gcrf); !ok) return ok.error();
  return world;
}

// The commanded attitude (zenith pointing, slews for observations towards the target's apparent
// direction) turned by the ADCS's control error; the attitude it reports, with its determination
// error; the attitude-dependent drag area.
void TruthWorld::update_attitude(core::GpsTime t, double t_s) {
  for (TruthSpacecraft& x : craft_) {
    x.target_unit_gcrf = sky_.target_unit_gcrf(t, x.x_gcrf);
    x.adcs->step(t_s);
    x.q_body_to_gcrf = x.adcs->true_attitude(x.attitude->body_to_gcrf(t_s, x.x_gcrf.r, x.x_gcrf.v, x.target_unit_gcrf));
    x.q_reported_body_to_gcrf = x.adcs->reported_attitude(x.q_body_to_gcrf);
    x.dynamics.forces->set_drag_area(x.drag.projected_area_m2(air_velocity_body_unit(x.x_gcrf, x.q_body_to_gcrf)));
  }
}

core::Result<ExecutedImpulse> TruthWorld::execute_impulse(std::size_t k, double t_s, const Eigen::Vector3d& dv_body_mps,
                                                          double tone_offset_s) {
  TruthSpacecraft& x = craft_[k];
  auto executed = x.propulsion->execute(t_s, dv_body_mps);
  if (!executed.ok()) return executed.error();
  const Eigen::Vector3d dv_gcrf = x.q_body_to_gcrf * executed->dv_executed_body_mps;
  x.x_gcrf.v += dv_gcrf;
  x.x_gcrf.r -= tone_offset_s * dv_gcrf;
  return executed;
}

void TruthWorld::apply_impulse_rtn(std::size_t k, const Eigen::Vector3d& dv_rtn_mps) {
  core::StateVector& x = craft_[k].x_gcrf;
  x.v += core::gcrf_to_rtn_matrix(x).transpose() * dv_rtn_mps;
}

core::Result<bool> TruthWorld::propagate(core::GpsTime t, double step_s) {
  for (TruthSpacecraft& x : craft_) {
    auto next = x.dynamics.propagator->propagate_to(t, x.x_gcrf, t + step_s);
    if (!next.ok()) return core::Error{std::string(x.name) + " truth", next.error().describe()};
    x.x_gcrf = *next;
  }
  return true;
}

Eigen::Vector3d TruthWorld::drag_acceleration_gcrf(std::size_t k, core::GpsTime t) const {
  const TruthSpacecraft& x = craft_[k];
  return x.dynamics.forces->acceleration_terms(t, x.x_gcrf).drag;
}

double TruthWorld::drag_area_m2(std::size_t k) const { return craft_[k].dynamics.forces->spacecraft().drag_area; }

nlohmann::json TruthWorld::summary() const {
  const auto vector = [](const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json out;
  for (const TruthSpacecraft& x : craft_) {
    out[std::string(x.name)] = {{"com_body_m", vector(x.geometry->com_body_m())},
                                {"payload_body_m", vector(x.geometry->payload_body_m())},
                                {"payload_axis_body", vector(x.geometry->payload_axis_body())},
                                {"phase_center_error_body_m", vector(x.geometry->phase_center_error_body_m())},
                                {"mass_kg", x.true_spacecraft.mass_kg},
                                {"cd", x.true_spacecraft.cd},
                                {"cr", x.true_spacecraft.cr},
                                {"isp_s", x.propulsion->isp_s()},
                                {"nozzle_bias", x.propulsion->nozzle_bias()}};
  }
  return out;
}

}  // namespace visors::sim
