#pragma once
// The float Kalman filter of the baseline and its integer ambiguity resolution.
//
// State (kStates = 67): the rover's Earth-fixed position [m] and one single-difference (rover
// minus base) carrier-phase ambiguity per satellite and frequency [cycles], in fixed slots
// (ambiguity_index). SD rather than DD ambiguity states keep the state meaning the same when the
// reference satellite changes; the DD ambiguities the integer search needs are formed from them
// with their covariance by nav::DoubleDifferenceAmbiguities (flight code,
// docs/algorithms/ambiguity-resolution.md#single-to-double-differences).
//
// Dynamics: static - the position is constant; kinematic - white noise: each epoch the position
// restarts from the epoch's code solution with kinematic_position_sigma_m. SD ambiguities are
// constant with a small random walk; a slot is (re)initialised to (phase - code) / lambda with
// initial_ambiguity_sigma_cyc when its satellite rises, slips or returns after a gap.
//
// Update: all DD code and phase rows of the epoch at once with their correlated covariance,
// Joseph form. DD phase innovations beyond phase_gate_sigma innovation sigmas are slips missed by
// the loss-of-lock and geometry-free tests: the satellite's slot is reinitialised (its
// reference's, when most of a group fails) and the update redone.
//
// Ambiguity resolution (continuous and hold): the DD floats of the satellites used this epoch,
// through nav::resolve_ambiguities (success rate and ratio, partial fixing), then the fixed
// solution = the float state conditioned on the fixed integer combinations
// (nav::FixedSolutionUpdate, exact). A fix whose DD phase residuals fail the gate is refused
// (wrong-fix check, docs/algorithms/cdgps-filter.md#wrong-fix-check). Hold: an accepted full fix is
// also fed back to the float filter as a pseudo-measurement of variance hold_variance_cyc2.

#include <array>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "visors/baseline/baseline_settings.hpp"
#include "visors/baseline/double_difference_system.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"

namespace visors::baseline {

/// fix: every DD ambiguity of the epoch fixed; partial: a subset of integer combinations fixed
/// (partial fixing: the position is improved but not phase-determined); float; code: the DD code
/// solution only; none: no solution.
enum class SolutionStatus { kNone, kCode, kFloat, kPartial, kFix };

/// "none", "code", "float", "partial", "fix".
std::string_view to_string(SolutionStatus status);

struct RejectedObservation {
  int prn = 0;
  int frequency = 0;
  const char* reason = "";  // "loss_of_lock", "geometry_free_jump", "phase_gate", "reference_phase_gate", ...
};

struct FilterEpochResult {
  int phase_rows = 0;           // DD phase measurements used
  int code_rows = 0;            // DD code measurements used
  std::vector<RejectedObservation> rejected;
  bool float_ok = false;
  // Ambiguity resolution
  nav::AmbiguityFix fix{};
  Eigen::Index ambiguities = 0;  // DD ambiguities offered to the search
  bool fix_accepted = false;     // a fixed solution is available (full or partial fix, residuals passed)
  bool wrong_fix_refused = false;
  Eigen::Vector3d r_float_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_float_m2 = Eigen::Matrix3d::Zero();
  Eigen::Vector3d r_fixed_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d cov_fixed_m2 = Eigen::Matrix3d::Zero();
};

class BaselineFilter {
 public:
  static core::Result<BaselineFilter> create(const BaselineSettings& settings);

  [[nodiscard]] bool initialised() const { return initialised_; }
  [[nodiscard]] Eigen::Vector3d rover_position() const { return x_.head<3>(); }
  /// Starts (or, kinematic, restarts) the position at r with sigma on each axis [m].
  void set_position(const Eigen::Vector3d& r_m, double sigma_m);
  /// Ambiguity random walk over the time since the last epoch.
  void predict(core::GpsTime t);
  /// (Re)initialises the SD ambiguity slot to value_cyc.
  void reset_ambiguity(int frequency, int prn, double value_cyc);
  void release_ambiguity(int frequency, int prn);
  [[nodiscard]] bool ambiguity_active(int frequency, int prn) const;

  /// Measurement update with the epoch's single differences (computed at rover_position()),
  /// then ambiguity resolution (settings' mode).
  FilterEpochResult update(const std::vector<SingleDifference>& sds);

  BaselineFilter(BaselineFilter&&) noexcept;
  BaselineFilter& operator=(BaselineFilter&&) noexcept;
  ~BaselineFilter();

 private:
  struct Ambiguity;
  explicit BaselineFilter(const BaselineSettings& settings, std::unique_ptr<Ambiguity> ambiguity);
  bool gate_phase(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& groups, const DdSystem& s,
                  FilterEpochResult& result);
  void kalman_update(const DdSystem& s);
  void resolve(const std::vector<SingleDifference>& sds, const std::vector<DdGroup>& phase_groups, const DdSystem& s,
               FilterEpochResult& result);

  BaselineSettings settings_;
  Eigen::VectorXd x_;
  Eigen::MatrixXd P_;
  std::array<bool, kStates> active_{};
  bool initialised_ = false;
  core::GpsTime last_;
  Eigen::Vector3d r_lin_ = Eigen::Vector3d::Zero();  // rover position the epoch's residuals were computed at
  std::unique_ptr<Ambiguity> ambiguity_;
};

}  // namespace visors::baseline
