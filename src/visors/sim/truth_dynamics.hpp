#pragma once
// The truth force model and propagator of one spacecraft of a scenario (the [forces] model with
// the spacecraft's mass, Cd, Cr and SRP area; fixed-step RK4 at integration_step_s).

#include <memory>
#include <optional>
#include <string_view>

#include "visors/core/result.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/dynamics/orbit_propagator.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct TruthDynamics {
  std::unique_ptr<dynamics::ForceModel> forces;  // the propagator keeps a pointer: never moves
  std::optional<dynamics::OrbitPropagator> propagator;
};

/// The spacecraft's true values for one run: mass, Cd and Cr each nominal + N(0, its sigma), the
/// normal draw clamped at 5 sigma (three draws from `rng`, in that order, whatever the sigmas);
/// propellant and SRP area as given. What the flight software's [flight] values miss.
SpacecraftSettings draw_true_spacecraft(const SpacecraftSettings& nominal, RandomStream& rng);

/// Errors name "forces (<name>)" or the propagator setting.
core::Result<TruthDynamics> make_truth_dynamics(const CampaignScenario& scenario, const SpacecraftSettings& spacecraft,
                                                std::string_view name);

}  // namespace visors::sim
