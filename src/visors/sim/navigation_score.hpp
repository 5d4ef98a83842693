#pragma once
// The on-board navigation of a closed-loop run (`[navigation] mode = "cdgps"`) scored against the
// truth, per spacecraft: the errors of the solution each component uses at every step, the
// integer ambiguity resolution's fix and wrong-fix rates and its time to first fix (the
// navigation figures of Guffanti et al., AAS 23-149, 2023, sec. 5: always reported together).
//
// Errors of a solution at step t (truth at t, the chief's RTN axes of the truth):
//  - relative position: estimated deputy minus chief centre of mass, minus the truth's: what the
//    control and safety use; it holds the centre-of-mass knowledge error (the drawn geometry,
//    sim/spacecraft_geometry.hpp: a few mm per spacecraft), which no navigation can see;
//  - relative antenna position: the error of the antennas' relative position the estimate implies
//    (its centres of mass plus C (arp + pco + p), p the estimated phase-centre error) against the
//    true antennas: the position error plus R_osc (p_osc - l_osc) - R_dsc (p_dsc - l_dsc) (R the
//    true attitude, l the true minus the known lever arm from the centre of mass to the phase
//    centre in the body frame: FormationTruth): what the GPS measurements determine, the paper's
//    figure (as `visors nav`);
//  - relative velocity: estimated minus true inertial velocity difference.
// The score reads what the component outputs, its navigation telemetry record
// (gnc::NavigationTelemetry: the solution in use, its phase-centre and empirical-acceleration
// estimates, the last epoch's fix and its double-difference integers, the counters), as a ground
// segment would; the overload on the component itself (gnc::OnboardNavigation) gives the same
// results and goes once the callers read the records.
// Only the solutions the component uses (valid: OnboardNavigation::valid()) are scored; the steps
// with a solution not yet (or no longer) valid are counted. The statistics leave out the slews to and from the observations (the satellites in view change
// at 1.5 deg/s) where an acceptance figure is stated outside the slews
// (docs/requirements.md#navigation-acceptance-figures), and report them whole too.
// A fix is wrong (nav/fix_truth.hpp) when a double difference of a full fix, or an integer
// combination of double differences a partial fix constrains, differs from the truth's (the
// receivers' integer ambiguities and phase offsets of that epoch) by more than half a cycle; each
// processed epoch is scored once. From the record: a full fix's integers, a partial fix's
// combinations, what nav::wrong_fix reads from the component's report and fixed solution. The summary carries the counters of the last record. fix_rate counts every processed
// epoch, fix_rate_after_first_fix those from the first fixed one on (the float time after the cold
// start is time_to_first_fix_s). fix_rate_all_epochs counts every receiver time tag after the cold
// start (receiver_time_tags): the receiver measures at every step (CampaignSimulation), so these
// are the steps after it, and an epoch the filter never processed (a data gap, a GPS outage, the
// bus in safe mode, a peer epoch still awaited at the end) counts as not fixed.

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/gnc/onboard_navigation.hpp"
#include "visors/sim/gps_receiver.hpp"

namespace visors::sim {

/// The truth of both spacecraft at a step, as the score needs it.
struct FormationTruth {
  core::StateVector dsc_gcrf, osc_gcrf;
  Eigen::Matrix3d dsc_body_to_gcrf = Eigen::Matrix3d::Identity(), osc_body_to_gcrf = Eigen::Matrix3d::Identity();
  /// True minus known lever arm from the centre of mass to the antenna phase centre, body frame
  /// [m]: (c_nom - c_true) + the phase centre's error (calibration error, boresight tilt).
  Eigen::Vector3d dsc_lever_error_m = Eigen::Vector3d::Zero(), osc_lever_error_m = Eigen::Vector3d::Zero();
};

/// One spacecraft's navigation at a step (navigation.csv).
struct NavigationSample {
  bool valid = false;  // a solution exists
  bool fixed = false;  // its last update was fixed
  Eigen::Vector3d position_rtn_m = Eigen::Vector3d::Zero();   // relative, centres of mass
  Eigen::Vector3d antenna_rtn_m = Eigen::Vector3d::Zero();    // relative, knowledge error removed
  Eigen::Vector3d velocity_rtn_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d sigma_rtn_m = Eigen::Vector3d::Zero();      // the solution's 1-sigma relative position
  Eigen::Vector3d empirical_dsc_rtn_mps2 = Eigen::Vector3d::Zero(), empirical_osc_rtn_mps2 = Eigen::Vector3d::Zero();
};

class NavigationScore {
 public:
  /// A receiver's epoch as measured (its channels' true ambiguities and phase offset).
  void record_phase_truth(gnc::Spacecraft receiver, const GpsReceiverEpoch& epoch);

  /// Scores the solution of `who`'s navigation telemetry record of the step at t_s against the
  /// truth; in_slew: the step lies in a slew to or from an observation.
  NavigationSample score(gnc::Spacecraft who, const gnc::NavigationTelemetry& record, double t_s,
                         const FormationTruth& truth, bool in_slew);
  /// The same from the component's navigation itself (to go: file comment).
  NavigationSample score(gnc::Spacecraft who, const gnc::OnboardNavigation& navigation, double t_s,
                         const FormationTruth& truth, bool in_slew);

  /// summary.json's "navigation": per spacecraft (file comment), with the counters of its last
  /// scored record.
  [[nodiscard]] nlohmann::json summary() const;

 private:
  static constexpr int kTruthEpochs = 4;
  struct PhaseTruth {
    core::GpsTime t;
    int count = 0;
    std::array<int, gnss::kMaxGpsChannels> prn{};
    std::array<double, gnss::kMaxGpsChannels> cycles{};  // N + half cycle + receiver phase offset
  };
  struct Accumulator {
    std::int64_t steps = 0, steps_outside_slews = 0, steps_invalid = 0;
    double position_sq = 0.0, antenna_sq = 0.0, velocity_sq = 0.0;
    double antenna_outside_sq = 0.0, position_outside_sq = 0.0;
    double antenna_worst = 0.0, antenna_outside_worst = 0.0;
    std::int64_t epochs = 0, fixed = 0, wrong = 0;  // processed epochs
    std::int64_t epochs_before_first_fix = 0;      // fix_rate_after_first_fix counts from the first fix
    std::int64_t time_tags = 0;                    // steps after the cold start (fix_rate_all_epochs)
    bool have_scored = false;
    core::GpsTime last_scored;
    double first_solution_s = -1.0, first_fix_s = -1.0;
    bool have_counters = false;
    gnc::NavigationCounters counters;  // of the last scored step
  };
  /// A solution as the score needs it, from either source.
  struct Estimate {
    core::StateVector dsc_gcrf, osc_gcrf;
    Eigen::Vector3d p_dsc_body_m, p_osc_body_m;
    Eigen::Vector3d empirical_dsc_rtn_mps2, empirical_osc_rtn_mps2;
    Eigen::Vector3d sigma_rtn_m;
    bool fixed = false;
  };

  [[nodiscard]] const PhaseTruth* phase_truth(gnc::Spacecraft receiver, core::GpsTime t) const;
  /// The true single difference of `prn` at the epoch of `dsc` and `osc` (NaN when either
  /// receiver did not track it) [cycles].
  [[nodiscard]] static double true_sd(const PhaseTruth& dsc, const PhaseTruth& osc, int prn);
  [[nodiscard]] bool wrong_fix(const gnc::OnboardNavigation& navigation, core::GpsTime t) const;
  [[nodiscard]] bool wrong_fix(const gnc::NavigationTelemetry& record) const;
  /// Counts the cold start, the step and the processed epochs up to the step; true when the
  /// last epoch is new and fixed (its fix is to be judged).
  static bool count_step(Accumulator& a, bool has_solution, const gnc::NavigationCounters& counters, core::GpsTime update_t,
                         bool fix_applied, double t_s);
  static NavigationSample add_solution(Accumulator& a, const Estimate& e, const FormationTruth& truth, bool in_slew);

  std::array<std::array<PhaseTruth, kTruthEpochs>, 2> truth_{};
  std::array<int, 2> next_truth_{};
  std::array<Accumulator, 2> stats_{};
};

}  // namespace visors::sim
