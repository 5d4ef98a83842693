#pragma once
// The figures of merit of a closed-loop run (ground side of the simulator): each observation
// attempt scored on the true payload points over its window (sim/alignment_metrics.hpp), the
// minimum separations, the delta-v executed by mode, the on-board navigation against the truth
// (sim/navigation_score.hpp), the flight components' step times, and the rows of the run
// directory's time series, navigation.csv and alignment_samples.csv (sim/run_recorder.hpp).

#include <array>
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include <optional>

#include "visors/control/guidance.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/sim/alignment_metrics.hpp"
#include "visors/sim/error_budget.hpp"
#include "visors/sim/navigation_score.hpp"
#include "visors/sim/run_recorder.hpp"
#include "visors/sim/truth_world.hpp"

namespace visors::sim {

class HostApplication;
class Sensors;

class RunMetrics {
 public:
  /// step_s: the simulation step (the drag prediction's impulses) [s].
  RunMetrics(RunRecorder& recorder, int observations, double step_s);

  /// An attempt the active spacecraft scheduled: scored over [start_s, end_s] [s since t0].
  void open_observation(int index, double start_s, double end_s);
  /// The executed impulse of spacecraft k in `mode`: its L1 norm in the thrusters' frame [m/s].
  void add_delta_v(std::size_t k, gnc::Mode mode, double l1_mps);
  /// The aim the flight software computes (its target direction, sim/error_budget.hpp): t0 and
  /// the science geometry it is configured with.
  void set_aim(core::GpsTime t0, const control::ScienceGeometry& geometry);
  /// The execution error of spacecraft k's impulse at t_s (true minus intended velocity change,
  /// GCRF [m/s]), with the DSC's true state then: the error budget's last burn.
  void add_impulse_error(std::size_t k, double t_s, const Eigen::Vector3d& dv_error_gcrf_mps, const core::StateVector& dsc_gcrf);

  /// Each component's navigation solution at t_s against the truth (the antenna lever against
  /// the one the flight software is told, `told`); `in_slew`: the step is in a slew to or from an
  /// observation.
  void score_navigation(const TruthWorld& truth, const Sensors& sensors, const HostApplication& host,
                        const FlightKnowledge& told, double t_s, bool in_slew);
  [[nodiscard]] NavigationScore& navigation_score() { return navigation_score_; }

  /// This step's alignment samples (closing the attempts that ended) and minimum separations;
  /// every `output_every` steps the time series and, with on-board navigation, navigation.csv.
  void record(const TruthWorld& truth, const HostApplication& host, core::GpsTime t, double t_s, std::int64_t step,
              std::int64_t output_every,
              const core::EarthGravityConstants& gravity, bool navigation, bool in_slew, bool in_observation);

  [[nodiscard]] std::array<std::vector<float>, 2>& step_us() { return step_us_; }

  /// summary.json's observations, success rate, separations, delta-v, step times.
  void add_to_summary(nlohmann::json& summary, const std::array<std::string_view, 2>& names) const;
  /// summary.json's "navigation": the score with each component's counters.
  [[nodiscard]] nlohmann::json navigation_summary(const HostApplication& host) const;
  [[nodiscard]] const AlignmentRequirements& requirements() const { return requirements_; }

 private:
  struct PendingObservation {
    AlignmentResult result;
    std::optional<ErrorBudget> budget;  // at the worst lateral sample, with on-board navigation
    double start_s = 0.0, end_s = 0.0;
    bool done = false;
  };
  // The last impulse's execution error in the DSC's RTN frame then, and the mean motion.
  struct LastBurn {
    double t_s = 0.0;
    Eigen::Vector3d dv_rtn_mps = Eigen::Vector3d::Zero();  // relative: OSC minus DSC
    double n_radps = 0.0;
  };
  // One step's drag prediction error as an impulse: (true differential drag - the planners'
  // estimate) * step, DSC RTN at its time, OSC minus DSC [m/s].
  struct DragImpulse {
    double t_s = 0.0;
    Eigen::Vector3d dv_rtn_mps = Eigen::Vector3d::Zero();
  };
  void record_drag_prediction(const TruthWorld& truth, const HostApplication& host, core::GpsTime t, double t_s);
  void sample_alignment(PendingObservation& p, const TruthWorld& truth, const HostApplication& host, double t_s);
  [[nodiscard]] std::optional<ErrorBudget> budget_at(const TruthWorld& truth, const HostApplication& host, double t_s) const;
  void close_observation(PendingObservation& p, double t_s);
  void record_navigation_rows(const HostApplication& host, double t_s, bool in_slew, bool in_observation);

  RunRecorder* recorder_;
  AlignmentRequirements requirements_;
  std::vector<PendingObservation> observations_;
  double min_sep_rn_m_ = std::numeric_limits<double>::infinity();
  double min_sep_3d_m_ = std::numeric_limits<double>::infinity();
  std::array<std::array<double, gnc::kModeCount>, 2> dv_by_mode_mps_{};  // executed, L1 in the thrusters' frame
  std::array<double, 2> dv_total_mps_{};
  NavigationScore navigation_score_;
  std::optional<LastBurn> last_burn_;
  double step_s_ = 1.0;
  std::vector<DragImpulse> drag_since_burn_;  // within kDragLookback_s of a pending observation
  core::GpsTime aim_t0_;
  control::ScienceGeometry aim_geometry_;
  std::array<NavigationSample, 2> navigation_samples_{};
  std::array<std::int64_t, 2> rows_epochs_{}, rows_fixed_{};  // at each spacecraft's last navigation.csv row
  std::array<std::vector<float>, 2> step_us_;  // wall time of each component step [us]
};

}  // namespace visors::sim
