#pragma once
// The closed-loop mission simulation of `visors run`: four parts stepped together at the 1 Hz
// channel rate, each in its own file, the truth and the flight software meeting only through
// messages:
//   - the truth world (sim/truth_world.hpp): both spacecraft under the truth force model, their
//     attitude with the bus ADCS's errors and drag area, propulsion with its errors, geometry;
//   - the sensors (sim/sensors.hpp): GPS receivers in the true pose, ephemeris decoding, the
//     computers' time at tone, the rangefinder, ideal navigation;
//   - the host application (sim/host_application.hpp): one GNC flight component per spacecraft
//     behind its binary channels, the ground timeline, the crosslink, the fault windows and the
//     host's FDIR policy table;
//   - the run metrics (sim/run_metrics.hpp): alignment, separations, delta-v, navigation score.
//
// One step() runs the phases in this order: truth attitude and drag area, ground timeline, fault
// windows, sensors and flight components, navigation score, then per spacecraft the host's
// routing (crosslink, observation windows to the truth attitude, impulses to the truth
// propulsion) and its FDIR, injected faults, metrics, end-of-campaign test, truth propagation.
// run_campaign() drives it and writes the run directory.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/gps_world.hpp"
#include "visors/sim/host_application.hpp"
#include "visors/sim/host_records.hpp"
#include "visors/sim/run_metrics.hpp"
#include "visors/sim/run_recorder.hpp"
#include "visors/sim/sensors.hpp"
#include "visors/sim/truth_world.hpp"

namespace visors::sim {

struct RunProgress {
  double simulated_s = 0.0;
  double total_s = 0.0;  // the current end of the campaign (max_duration_s until it is known)
  double wall_s = 0.0;
};

/// How a run uses the host (not part of the scenario: the results are the same bit for bit).
struct RunOptions {
  /// Step the two flight components on two threads (sim/paired_worker.hpp) when the host has two
  /// cores or more (`visors run --threads 2`, its default). Off by default here: the test suite
  /// and a Monte Carlo campaign run one simulation per core instead.
  bool parallel_components = false;
  /// Run each spacecraft's flight software as a process started by this command (`visors run
  /// --fsw process`: the visors-fsw program, or an emulator and the program;
  /// sim/flight_software.hpp); empty: the components run in this process.
  std::vector<std::string> fsw_command;
};

struct RunResult {
  nlohmann::json summary;
  std::filesystem::path dir;
};

class CampaignSimulation {
 public:
  /// Sets up both spacecraft at the scenario's initial formation (the scenario is copied);
  /// events (data-file fallbacks first) go to `recorder`, which must outlive the simulation.
  /// Errors name the scenario field.
  static core::Result<CampaignSimulation> create(const CampaignScenario& scenario, RunRecorder& recorder,
                                                 const RunOptions& options = {});

  /// Runs the step at the current time and advances the truth to the next one. Returns false,
  /// without doing anything, once the campaign has ended. Errors: a truth state that fails.
  core::Result<bool> step();

  /// Time of the last step run; once ended, the time at which the campaign stopped [s since t0].
  [[nodiscard]] double time_s() const { return ts_; }
  /// The current end of the campaign: max_duration_s until the last mode change sets it [s].
  [[nodiscard]] double end_s() const { return end_s_; }
  [[nodiscard]] bool ended() const { return ended_; }
  /// The figures of merit (docs/run-directory.md, summary.json), `wall_s` as given.
  [[nodiscard]] nlohmann::json summary(double wall_s) const;
  [[nodiscard]] nlohmann::json truth_summary() const;

 private:
  CampaignSimulation(const CampaignScenario& scenario, RunRecorder& recorder, TruthWorld truth, Sensors sensors,
                     HostApplication host);

  // The phases of step(), in order.
  core::Result<bool> step_flight_components(core::GpsTime t);
  void measure(std::size_t k, const EpochFrame& frame, core::GpsTime t, HostRecords& records);
  void route_outputs(std::size_t k);
  void execute_maneuver(std::size_t k, core::GpsTime t);
  void inject_faults(core::GpsTime t);
  void update_end();
  [[nodiscard]] bool in_slew(double t_s) const;
  [[nodiscard]] bool in_observation(double t_s) const;

  CampaignScenario scenario_;
  RunRecorder* recorder_;
  TruthWorld truth_;
  Sensors sensors_;
  HostApplication host_;
  RunMetrics metrics_;
  // Step indices of the timeline (-1: never).
  std::int64_t steps_total_ = 0, output_every_ = 1, fault_step_ = -1, non_gnc_fault_step_ = -1;
  std::int64_t k_ = 0;  // the next step to run
  double ts_ = 0.0;     // time of the last step run [s since t0]
  double end_s_ = 0.0;
  bool ended_ = false;
  bool left_science_ = false, escaped_ = false;
  std::array<HostRecords, 2> host_records_;  // this step's input records of each component
  std::vector<std::string> fallbacks_;         // embedded defaults used for missing data (the warnings)
};

/// Runs `scenario`, writing the run directory `out_dir`. `progress` (optional) is called about
/// every simulated minute. Errors: model set-up (named field), output files, a truth state
/// that fails (re-entry).
core::Result<RunResult> run_campaign(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                     const std::function<void(const RunProgress&)>& progress = {},
                                     const RunOptions& options = {});

}  // namespace visors::sim
