#pragma once
// Writes the run directory of `visors run` (docs/run-directory.md): the resolved scenario, the
// time series, the observations, the event log and summary.json. Rows are streamed to the files
// as the run goes (a crash leaves what was simulated), numbers with 17 significant digits.

#include <array>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "visors/core/files/output_file.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/sim/alignment_metrics.hpp"
#include "visors/sim/error_budget.hpp"
#include "visors/sim/navigation_score.hpp"

namespace visors::sim {

/// Version of the run directory's format (docs/run-directory.md), written in summary.json as
/// `format_version`. 3: the refused inputs in one set, `inputs_refused` by reason and channel
/// (was `records_refused` by record status), and `rejected_inputs` counts them all. 2: an
/// observation's start in summary.json is `t_s` (was `t_gps`, which was never GPS time);
/// `format_version` itself is new (absent means 1).
inline constexpr int kRunDirectoryFormatVersion = 3;

struct TimeseriesRow {
  double t_s = 0.0;
  std::string_view mode;
  std::string_view active;
  Eigen::Matrix<double, 6, 1> roe_mean_m = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Matrix<double, 6, 1> roe_osc_m = Eigen::Matrix<double, 6, 1>::Zero();
  Eigen::Vector3d r_rtn_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_rtn_mps = Eigen::Vector3d::Zero();
  double sep_rn_m = 0.0, sep_3d_m = 0.0;
  bool has_margin = false;
  double safety_margin_m = 0.0;
  double dv_dsc_mps = 0.0, dv_osc_mps = 0.0;
  std::array<double, 2> drag_area_m2{};  // DSC, OSC at their attitudes
  double drag_t_difference_mps2 = 0.0;   // true drag, OSC minus DSC, along the DSC's T axis
  bool has_drag_estimate = false;        // the active spacecraft's estimator is valid
  double drag_t_estimate_mps2 = 0.0;     // its estimate of drag_t_difference_mps2
};

class RunRecorder {
 public:
  /// Creates `dir` (and parents) and opens the files. Errors name the path.
  static core::Result<RunRecorder> open(const std::filesystem::path& dir, const std::string& scenario_toml);

  /// Opens navigation.csv (on-board navigation runs). Errors name the path.
  core::Result<bool> open_navigation();
  void timeseries(const TimeseriesRow& row);
  /// A navigation.csv row (open_navigation() first): the sample at t_s, the fraction of the
  /// processed epochs fixed since the spacecraft's previous row, where the step lies.
  void navigation(double t_s, std::string_view spacecraft, const NavigationSample& sample, double fixed_fraction,
                  bool in_slew, bool in_observation);
  /// An observations.csv row: the score, the pointing and the error budget (empty columns without one).
  void observation(const AlignmentResult& result, bool success, const std::optional<ErrorBudget>& budget);
  /// An alignment_samples.csv row: attempt `index` at t_s, both spacecraft's true centre-of-mass
  /// states (GCRF) and attitudes, the target's apparent direction from the DSC, the sample's values.
  void alignment_sample(int index, double t_s, const core::StateVector& dsc_gcrf, const Eigen::Quaterniond& q_dsc,
                        const core::StateVector& osc_gcrf, const Eigen::Quaterniond& q_osc,
                        const Eigen::Vector3d& target_unit_gcrf, const AlignmentSample& sample);
  void event(double t_s, std::string_view spacecraft, std::string_view kind, std::string_view detail);
  /// Writes flight_config.json (sim/flight_config.hpp). Errors name the path.
  core::Result<bool> flight_config(const nlohmann::json& config) const;
  /// Writes summary.json and closes the files.
  core::Result<bool> finish(const nlohmann::json& summary);

  [[nodiscard]] const std::filesystem::path& dir() const { return dir_; }

  RunRecorder(RunRecorder&&) noexcept = default;
  RunRecorder& operator=(RunRecorder&&) noexcept = default;
  ~RunRecorder() = default;

 private:
  using File = core::files::OutputFile;
  RunRecorder() = default;

  std::filesystem::path dir_;
  File timeseries_, observations_, events_, navigation_, alignment_samples_;
};

}  // namespace visors::sim
