#pragma once
// The truth world of the closed-loop campaign (ground side of the simulator): both spacecraft's
// state under the truth force model, their commanded attitude turned by the bus ADCS's errors
// (sim/adcs_model.hpp) with the attitude-dependent drag area, their propulsion executing impulses
// with its errors, their drawn geometry and ballistic properties, and the sky (the target's
// apparent direction, sim/sky_truth.hpp). It knows nothing of the flight software: the host
// application hands it the observation windows to slew for and the impulses to execute.

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/sim/adcs_model.hpp"
#include "visors/sim/attitude_profile.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/drag_area.hpp"
#include "visors/sim/propulsion.hpp"
#include "visors/sim/sky_truth.hpp"
#include "visors/sim/spacecraft_geometry.hpp"
#include "visors/sim/truth_dynamics.hpp"

namespace visors::sim {

/// One spacecraft's truth.
struct TruthSpacecraft {
  gnc::Spacecraft id = gnc::Spacecraft::kDsc;
  std::string_view name;  // "dsc" or "osc": event log, error fields, random stream names
  TruthDynamics dynamics;  // force model and propagator
  core::StateVector x_gcrf;
  Eigen::Quaterniond q_body_to_gcrf = Eigen::Quaterniond::Identity();  // the attitude the bus holds
  /// The attitude the ADCS reports this step (its determination error included).
  Eigen::Quaterniond q_reported_body_to_gcrf = Eigen::Quaterniond::Identity();
  /// The spacecraft's true mass, Cd and Cr this run (draw_true_spacecraft of its truth keys).
  SpacecraftSettings true_spacecraft;
  /// The observation target's apparent direction from this spacecraft this step.
  Eigen::Vector3d target_unit_gcrf = Eigen::Vector3d::UnitX();
  std::optional<AttitudeProfile> attitude;  // the commanded attitude (slews at the ADCS's rate)
  std::optional<AdcsModel> adcs;            // its control error and the error of what it reports
  DragArea drag = DragArea::visors_6u();
  std::optional<Propulsion> propulsion;
  std::optional<SpacecraftGeometry> geometry;

  /// The true payload reference point (GCRF) [m].
  [[nodiscard]] Eigen::Vector3d payload_gcrf_m() const {
    return x_gcrf.r + q_body_to_gcrf * geometry->payload_from_com_body_m();
  }
};

class TruthWorld {
 public:
  /// Both spacecraft at their initial states (DSC, OSC), their truth keys drawn (streams
  /// "<name>.ballistics", "<name>.propulsion", "<name>.adcs", "<name>.geometry"). Errors name the
  /// scenario field.
  static core::Result<TruthWorld> create(const CampaignScenario& scenario, const core::StateVector& dsc0_gcrf,
                                         const core::StateVector& osc0_gcrf);

  /// The target's apparent direction, the ADCS's errors, the true and reported attitudes and the
  /// drag area at t (t_s since t0).
  void update_attitude(core::GpsTime t, double t_s);

  /// Executes an impulse commanded in the body frame at t_s (with the propulsion's errors) at the
  /// instant tone_offset_s after t_s, when the commanding computer's tone really happened
  /// (sim/host_clock.hpp): the velocity change, and the position change -offset * dv it implies.
  core::Result<ExecutedImpulse> execute_impulse(std::size_t k, double t_s, const Eigen::Vector3d& dv_body_mps,
                                                double tone_offset_s);

  /// An unplanned impulse (a stuck valve) in the spacecraft's own RTN axes [m/s].
  void apply_impulse_rtn(std::size_t k, const Eigen::Vector3d& dv_rtn_mps);

  /// Propagates both spacecraft from t to t + step_s. Errors: a state that fails (re-entry).
  core::Result<bool> propagate(core::GpsTime t, double step_s);

  TruthSpacecraft& operator[](std::size_t k) { return craft_[k]; }
  const TruthSpacecraft& operator[](std::size_t k) const { return craft_[k]; }
  [[nodiscard]] std::array<TruthSpacecraft, 2>& craft() { return craft_; }
  [[nodiscard]] const std::array<TruthSpacecraft, 2>& craft() const { return craft_; }

  /// The drag acceleration of spacecraft k at t in its present state and attitude, GCRF [m/s^2]
  /// (t must be the time of the present state: the propagator evaluates the same at its next
  /// step, so the force model's time caches are unchanged).
  [[nodiscard]] Eigen::Vector3d drag_acceleration_gcrf(std::size_t k, core::GpsTime t) const;
  /// The drag area of spacecraft k at its present attitude [m^2].
  [[nodiscard]] double drag_area_m2(std::size_t k) const;

  /// What the run drew for each spacecraft (docs/run-directory.md "truth"): the body vectors
  /// from the structural origin, the true mass, Cd, Cr, the propulsion's Isp and nozzle biases.
  [[nodiscard]] nlohmann::json summary() const;

 private:
  explicit TruthWorld(const CampaignScenario& scenario) : sky_(scenario.target_offset_rad) {}

  std::array<TruthSpacecraft, 2> craft_;  // dsc, osc
  SkyTruth sky_;
};

}  // namespace visors::sim
