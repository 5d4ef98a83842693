#pragma once
// One spacecraft of the closed-loop campaign as the simulator holds it: its truth (state, force
// model and propagator, commanded attitude, ADCS errors and drag area, propulsion with its errors, payload
// geometry with its errors), its sensors (ideal navigation, the crosslink inbox), its GNC flight
// component, and what the host application keeps for it (commands and telemetry to deliver at the
// next step, FDIR persistence, executed delta-v).

#include <array>
#include <optional>
#include <string_view>

#include <Eigen/Geometry>

#include "core/state_vector.hpp"
#include "core/status.hpp"
#include "gnc/record_interface.hpp"
#include "sim/adcs_model.hpp"
#include "sim/attitude_profile.hpp"
#include "sim/campaign_scenario.hpp"
#include "sim/crosslink.hpp"
#include "sim/drag_area.hpp"
#include "gnss/gps_constants.hpp"
#include "sim/gps_receiver.hpp"
#include "sim/gps_world.hpp"
#include "sim/host_clock.hpp"
#include "sim/ideal_navigation.hpp"
#include "sim/propulsion.hpp"
#include "sim/spacecraft_geometry.hpp"
#include "sim/truth_dynamics.hpp"

namespace visors::sim {

struct SimulatedSpacecraft {
  gnc::Spacecraft id = gnc::Spacecraft::kDsc;
  std::string_view name;  // "dsc" or "osc": event log, error fields, random stream names
  // Truth.
  TruthDynamics truth;  // force model and propagator
  core::StateVector x_gcrf;
  Eigen::Quaterniond q_body_to_gcrf = Eigen::Quaterniond::Identity();
  /// The spacecraft's true mass, Cd and Cr this run (draw_true_spacecraft of its truth keys).
  SpacecraftSettings true_spacecraft;
  /// The observation target's apparent direction from this spacecraft this step (sim/sky_truth.hpp).
  Eigen::Vector3d target_unit_gcrf = Eigen::Vector3d::UnitX();
  std::optional<AttitudeProfile> attitude;  // the commanded attitude (slews at the ADCS's rate)
  std::optional<AdcsModel> adcs;            // its control error and the error of what it reports
  /// The attitude the ADCS reports to the flight component this step (time at tone).
  Eigen::Quaterniond q_reported_body_to_gcrf = Eigen::Quaterniond::Identity();
  std::optional<HostClock> clock;  // when its computer's time at tone really happens
  DragArea drag = DragArea::visors_6u();
  std::optional<Propulsion> propulsion;
  std::optional<SpacecraftGeometry> geometry;
  // Sensors and the flight component.
  std::optional<IdealNavigation> navigation;  // [navigation] mode = "ideal"
  std::optional<GpsReceiver> receiver;        // [navigation] mode = "cdgps"
  /// Per PRN, the next broadcast data set the receiver has not decoded yet (CampaignSimulation).
  std::array<std::size_t, gnss::kMaxGpsPrn + 1> next_ephemeris{};
  std::optional<Crosslink<gnc::OutputRecords::Record>> inbox;  // crosslink records from the other spacecraft
  std::optional<gnc::RecordInterface> gnc;  // the flight component behind its binary channels
  gnc::GncOutputs out;  // of the last step, decoded from its output records
  gnc::OutputRecords::Record crosslink_out;  // the last step's crosslink record (size 0: none), as sent
  // Host application: the sequence numbers of the records it writes, per channel.
  std::array<std::uint32_t, gnc::kChannels + 1> sequence{};
  // Host application.
  std::optional<gnc::PropulsionTelemetry> telemetry;  // delivered at the next step
  std::optional<gnc::GroundCommand> command;          // delivered at the next step
  std::optional<gnc::GroundCommand> command_after;    // delivered at the step after (one command a step)
  bool violation_reported = false;
  double incapable_since_s = -1.0;  // since when GNC incapable is reported, -1 if not
  std::array<double, gnc::kModeCount> dv_by_mode_mps{};  // executed, L1 in the thrusters' frame
  double dv_total_mps = 0.0;
};

/// Sets up `v` (its `id` and `name` already set) for `scenario`: truth models, propulsion,
/// attitude, geometry draw, flight component (`active` role), ideal navigation and inbox, with
/// random streams named after the spacecraft; with `gps` ([navigation] mode = "cdgps") the GPS
/// receiver (as `visors gnss-sim`'s: RandomStream(seed, "<name>.gps"), the world's ionosphere)
/// and the component's on-board navigation. Errors name the scenario field.
/// `nominal`: the spacecraft's truth keys; its true values are drawn from them
/// (draw_true_spacecraft, stream "<name>.ballistics"), the flight component is told
/// scenario.flight's.
core::Result<bool> set_up_spacecraft(SimulatedSpacecraft& v, const CampaignScenario& scenario,
                                     const SpacecraftSettings& nominal, bool active, const core::StateVector& x0_gcrf,
                                     const GpsWorld* gps = nullptr);

}  // namespace visors::sim
