#pragma once
// The closed-loop mission simulation of `visors run`: the truth world (both spacecraft under the
// truth force model, attitude profile and attitude-dependent drag area, propulsion with its
// errors, payload geometry with its errors), ideal navigation, a delayed crosslink, the host
// application emulator (channel routing, the ground timeline, FDIR responses) and one GNC
// flight component per spacecraft, stepped together at the 1 Hz channel rate.
//
// Host application (mission paper, FDIR): ground commands follow the scenario timeline
// (to_standby at t0, start_science after standby_s); when the active spacecraft reports a
// passive-safety violation the host commands it to escape; when the active spacecraft reports
// GNC incapable for a minute, the host switches roles (the other spacecraft becomes active).
//
// CampaignSimulation is the object; one step() runs the phases in this order: truth attitude and
// drag area, ground timeline, sensors and flight components, then per spacecraft the host's
// routing and actuators and its FDIR, injected faults, metrics, end-of-campaign test, truth
// propagation. run_campaign() drives it and writes the run directory.

#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/status.hpp"
#include "sim/alignment_metrics.hpp"
#include "sim/campaign_scenario.hpp"
#include "sim/gps_world.hpp"
#include "sim/host_records.hpp"
#include "sim/navigation_score.hpp"
#include "sim/paired_worker.hpp"
#include "sim/run_recorder.hpp"
#include "sim/simulated_spacecraft.hpp"
#include "sim/sky_truth.hpp"

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
  struct PendingObservation {
    AlignmentResult result;
    double start_s = 0.0, end_s = 0.0;
    bool done = false;
  };

  CampaignSimulation(const CampaignScenario& scenario, RunRecorder& recorder, const RunOptions& options);
  core::Result<bool> set_up_gps();
  [[nodiscard]] nlohmann::json navigation_summary() const;
  SimulatedSpacecraft& active();
  [[nodiscard]] const SimulatedSpacecraft& active() const;

  // The phases of step(), in order.
  void update_attitude(core::GpsTime t);
  void apply_ground_timeline(core::GpsTime t);
  void step_flight_components(core::GpsTime t);
  void read_outputs(SimulatedSpacecraft& v, const gnc::OutputRecords& out);
  void score_navigation();
  void route_outputs(SimulatedSpacecraft& v, SimulatedSpacecraft& other);
  void execute_maneuver(SimulatedSpacecraft& v, core::GpsTime t);
  void apply_fdir(SimulatedSpacecraft& v, SimulatedSpacecraft& other, core::GpsTime t);
  void inject_faults(core::GpsTime t);
  void open_fault_windows(core::GpsTime t);
  void close_fault_windows(core::GpsTime t);
  /// The non-GNC fault of a spacecraft that can no longer act (bus safe mode, failed thruster).
  void switch_away_from(std::size_t victim, core::GpsTime t, std::string_view what);
  [[nodiscard]] bool in_window(const FaultWindow& window, int victim, std::size_t k) const;
  void record_metrics();
  void update_end();
  core::Result<bool> propagate_truth(core::GpsTime t);
  // Sensors of on-board navigation ([navigation] mode = "cdgps").
  std::optional<gnc::GpsMessage> measure_gps(SimulatedSpacecraft& v, const EpochFrame& frame, core::GpsTime t);
  void decode_ephemeris(SimulatedSpacecraft& v, core::GpsTime t, gnc::GpsMessage& message);
  std::optional<gnc::LaserRange> measure_range(core::GpsTime t);
  [[nodiscard]] bool in_slew(double t_s) const;
  [[nodiscard]] bool in_observation(double t_s) const;

  CampaignScenario scenario_;
  RunRecorder* recorder_;
  std::array<SimulatedSpacecraft, 2> vehicles_;  // dsc, osc
  AlignmentRequirements requirements_;
  std::vector<PendingObservation> observations_;
  // Step indices of the timeline (-1: never).
  std::int64_t steps_total_ = 0, output_every_ = 1, science_step_ = 0, fault_step_ = -1, non_gnc_fault_step_ = -1;
  std::int64_t k_ = 0;  // the next step to run
  double ts_ = 0.0;     // time of the last step run [s since t0]
  double end_s_ = 0.0;
  bool ended_ = false;
  double min_sep_rn_m_ = std::numeric_limits<double>::infinity();
  double min_sep_3d_m_ = std::numeric_limits<double>::infinity();
  int safety_violations_ = 0;
  bool science_started_ = false, left_science_ = false, escaped_ = false;
  // On-board navigation ([navigation] mode = "cdgps").
  std::optional<GpsWorld> gps_;
  /// Per PRN, the indices of its broadcast data sets in GpsSatelliteTruth::broadcast_records(),
  /// in t_oe order.
  std::array<std::vector<std::size_t>, gnss::kMaxGpsPrn + 1> sets_by_prn_;
  std::optional<RandomStream> lrf_rng_;
  core::InterpolatedEarthFrame earth_frame_;
  SkyTruth sky_;  // the apparent Sun and target (the truth's own computation)
  NavigationScore navigation_score_;
  std::array<NavigationSample, 2> navigation_samples_{};
  std::array<std::int64_t, 2> rows_epochs_{}, rows_fixed_{};  // at each spacecraft's last navigation.csv row
  // Fault windows ([fault]): the spacecraft each concerns (index, -1 before the window opens).
  int gps_outage_victim_ = -1, safe_mode_victim_ = -1, thruster_victim_ = -1;
  std::optional<RandomStream> garbage_rng_;
  std::array<std::vector<float>, 2> step_us_;  // wall time of each component step [us]
  std::array<HostRecords, 2> host_records_;    // this step's input records of each component
  std::vector<std::string> fallbacks_;          // embedded defaults used for missing data (the warnings)
  std::unique_ptr<PairedWorker> components_;   // steps the two components (a pointer: movable)
};

/// Runs `scenario`, writing the run directory `out_dir`. `progress` (optional) is called about
/// every simulated minute. Errors: model set-up (named field), output files, a truth state
/// that fails (re-entry).
core::Result<RunResult> run_campaign(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                     const std::function<void(const RunProgress&)>& progress = {},
                                     const RunOptions& options = {});

}  // namespace visors::sim
