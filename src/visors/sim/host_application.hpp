#pragma once
// The host application of both spacecraft as the campaign emulates it (the hosted software app
// around GNC of Guffanti et al., AAS 23-149, 2023, sec. 4.1): one GNC flight component per
// spacecraft behind its binary channels, the ground timeline, the crosslink between the two, the
// commands and telemetry it queues for the next step, the fault windows the scenario injects, and
// the host's FDIR.
//
// FDIR policy (the same paper, sec. 4.1, FDIR; docs/architecture.md#fdir), one table (kFdirPolicy):
// a trigger of the active spacecraft and its response, which may depend on whether the formation is
// in science (science or the transfer to it) at the trigger:
//   passive-safety violation reported           -> escape (whatever the mode);
//   GNC incapable for 60 s (600 s before it     -> role switch;
//   was first capable), the other capable
//   a non-GNC fault it can ride out             -> in science: transfer to standby; else role switch;
//   unable to act (bus safe mode, failed        -> role switch; in science, then the new active
//   thruster)                                      one commanded back to standby the step after
//                                                  (the faulty one cannot fly the return).
// Commands are queued for the step at which the host delivers them (one command a step).

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnc/record_interface.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/crosslink.hpp"
#include "visors/sim/host_records.hpp"
#include "visors/sim/flight_software.hpp"
#include "visors/sim/random_stream.hpp"
#include "visors/sim/run_recorder.hpp"

namespace visors::sim {

/// The persistence of "GNC incapable" before the host switches roles (kFdirPolicy): 60 s once
/// the spacecraft has been capable, 600 s before. A cold start is not a fault: both spacecraft are
/// incapable until their first solution (the real sky's first fix comes 70-150 s after the
/// receivers start, the broadcast ephemerides being decoded 18-36 s after lock), and the one that
/// is first capable by a few seconds is no better a choice than the active one (docs/decisions.md,
/// "GNC incapable at the cold start"). A receiver that never delivers still hands over, after
/// 600 s.
struct GncIncapablePersistence {
  static constexpr double kAfterCapable_s = 60.0;
  static constexpr double kBeforeCapable_s = 600.0;
  double since_s = -1.0;  // since when incapable is reported, -1 if not
  bool ever_capable = false;
  /// One step's report at t_s [s]: whether the persistence has run out (then it restarts).
  bool due(bool incapable, double t_s);
};

/// One spacecraft's flight component and what the host keeps for it.
struct HostedComponent {
  gnc::Spacecraft id = gnc::Spacecraft::kDsc;
  std::string_view name;  // "dsc" or "osc"
  gnc::GncOutputs out;                       // of its last step, decoded from its output records
  gnc::OutputRecords::Record crosslink_out;  // its last step's crosslink record (size 0: none)
  HostRecords::Sequences sequence{};  // of the records the host writes, per channel
  std::optional<Crosslink<gnc::OutputRecords::Record>> inbox;  // crosslink records from the other
  std::optional<gnc::PropulsionTelemetry> telemetry;  // delivered at the next step
  std::optional<gnc::GroundCommand> command;          // delivered at the next step
  std::optional<gnc::GroundCommand> command_after;    // delivered at the step after
  bool violation_reported = false;
  GncIncapablePersistence incapable;
};

/// What sets off the host's FDIR (file comment).
enum class FdirTrigger : std::uint8_t { kSafetyViolation, kGncIncapable, kNonGncFault, kUnableToAct };
/// The host's responses.
enum class FdirResponse : std::uint8_t { kEscape, kRoleSwitch, kTransferToStandby, kRoleSwitchThenStandby };

struct FdirRule {
  FdirTrigger trigger;
  FdirResponse in_science;  // in science or the transfer to it
  FdirResponse otherwise;
};

inline constexpr std::array<FdirRule, 4> kFdirPolicy{{
    {FdirTrigger::kSafetyViolation, FdirResponse::kEscape, FdirResponse::kEscape},
    {FdirTrigger::kGncIncapable, FdirResponse::kRoleSwitch, FdirResponse::kRoleSwitch},
    {FdirTrigger::kNonGncFault, FdirResponse::kTransferToStandby, FdirResponse::kRoleSwitch},
    {FdirTrigger::kUnableToAct, FdirResponse::kRoleSwitchThenStandby, FdirResponse::kRoleSwitch},
}};

/// The response of kFdirPolicy to `trigger` in `mode`.
FdirResponse fdir_response(FdirTrigger trigger, gnc::Mode mode);

class HostApplication {
 public:
  /// The host of both flight components (`software`, created with on-board navigation when
  /// `gps`); the crosslink inboxes (streams "<name>.crosslink"). Errors name the scenario field.
  static core::Result<HostApplication> create(const CampaignScenario& scenario, RunRecorder& recorder, bool gps,
                                              FlightSoftware software);

  HostedComponent& operator[](std::size_t k) { return craft_[k]; }
  const HostedComponent& operator[](std::size_t k) const { return craft_[k]; }
  [[nodiscard]] std::size_t active_index() const { return craft_[0].out.telemetry.active ? 0 : 1; }

  /// Ground commands of step `step` (t_s since t0): to standby at t0, start science after standby_s.
  void apply_ground_timeline(std::int64_t step, core::GpsTime t, double t_s);
  [[nodiscard]] bool science_started() const { return science_started_; }

  // The fault windows ([fault]); each concerns the spacecraft active when it opens.
  /// Opens the windows that start at t_s (events; a bus safe mode is FDIR's "unable to act").
  /// Returns the spacecraft whose receiver clock jumps at this step, if any.
  std::optional<std::size_t> open_fault_windows(std::int64_t step, core::GpsTime t, double t_s);
  /// The first step after a safe mode: the spacecraft is back, and told it is passive now.
  void close_fault_windows(core::GpsTime t, double t_s);
  [[nodiscard]] bool in_safe_mode(std::size_t k, double t_s) const;
  [[nodiscard]] bool in_gps_outage(std::size_t k, double t_s) const;
  [[nodiscard]] bool thruster_failed(std::size_t k) const { return thruster_victim_ == static_cast<int>(k); }
  /// The garbage fault's records for spacecraft k at t, if its window is open at t_s.
  void add_garbage(std::size_t k, core::GpsTime t, double t_s, HostRecords& records);
  [[nodiscard]] bool crosslink_lost(double t_s) const { return scenario_fault_.crosslink_loss.contains(t_s); }

  /// Steps the components that are not in a bus safe mode with their records (side by side:
  /// sim/flight_software.hpp) and decodes their outputs; mode changes go to the event log.
  /// `stepped` says which; each step's wall time goes to `step_us`. Errors: a flight software
  /// process that stopped or broke its stream.
  core::Result<bool> step_components(core::GpsTime t, double t_s, const std::array<bool, 2>& stepped,
                       std::array<HostRecords, 2>& records, std::array<std::vector<float>, 2>& step_us);

  /// The host's FDIR on spacecraft k's outputs of this step (kFdirPolicy's first two triggers).
  void apply_fdir(std::size_t k, core::GpsTime t, double t_s);
  /// A trigger of kFdirPolicy on spacecraft `victim`, the commands delivered from `deliver_at`.
  void respond(FdirTrigger trigger, std::size_t victim, core::GpsTime deliver_at, double t_s, std::string_view what);
  [[nodiscard]] int safety_violations() const { return safety_violations_; }
  [[nodiscard]] const FlightSoftware& software() const { return software_; }

 private:
  HostApplication(const CampaignScenario& scenario, RunRecorder& recorder, FlightSoftware software);
  void read_outputs(std::size_t k, const gnc::OutputRecords& out, double t_s);
  void command(std::size_t k, gnc::GroundCommand::Kind kind, core::GpsTime at);

  std::array<HostedComponent, 2> craft_;  // dsc, osc
  RunRecorder* recorder_;
  FaultSettings scenario_fault_;
  double step_s_ = 1.0;
  int observations_ = 0;
  std::int64_t science_step_ = 0, clock_jump_step_ = -1;
  bool science_started_ = false;
  int safety_violations_ = 0;
  // The spacecraft each fault window concerns (index, -1 before the window opens).
  int gps_outage_victim_ = -1, safe_mode_victim_ = -1, thruster_victim_ = -1;
  bool gps_ = false;
  std::optional<RandomStream> garbage_rng_;
  std::uint64_t seed_ = 0;
  FlightSoftware software_;  // the two components
};

}  // namespace visors::sim
