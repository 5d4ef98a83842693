#include "visors/sim/truth_dynamics.hpp"

#include <algorithm>
#include <string>

#include "visors/dynamics/files/force_model_files.hpp"

namespace visors::sim {

SpacecraftSettings draw_true_spacecraft(const SpacecraftSettings& nominal, RandomStream& rng) {
  const auto deviation = [&rng](double sigma) { return sigma * std::clamp(rng.normal(), -5.0, 5.0); };
  SpacecraftSettings truth = nominal;
  truth.mass_kg += deviation(nominal.mass_sigma_kg);
  truth.cd += deviation(nominal.cd_sigma);
  truth.cr += deviation(nominal.cr_sigma);
  return truth;
}

core::Result<TruthDynamics> make_truth_dynamics(const CampaignScenario& s, const SpacecraftSettings& sc,
                                                std::string_view name) {
  TruthDynamics d;
  const dynamics::SpacecraftProperties props{sc.mass_kg, 0.35, sc.cd, sc.srp_area_m2, sc.cr};
  auto forces = dynamics::files::load_force_model(s.forces, props);
  if (!forces.ok()) return core::Error{"forces (" + std::string(name) + ")", forces.error().describe()};
  d.forces = std::make_unique<dynamics::ForceModel>(std::move(forces).value());
  dynamics::PropagatorSettings ps;
  ps.integrator = dynamics::IntegratorKind::kRk4Fixed;
  ps.step_s = s.integration_step_s;
  auto propagator = dynamics::OrbitPropagator::create(*d.forces, ps);
  if (!propagator.ok()) return propagator.error();
  d.propagator.emplace(std::move(propagator).value());
  return d;
}

}  // namespace visors::sim
