#pragma once
// The per-epoch scores of one filter's replay (`visors nav`), shared by its outputs: the CSV and
// summary (nav_command.cpp) and the HTML page (nav_page.cpp).

#include <array>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include "visors/core/state_vector.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav_app {

/// A state not known (NaN): written as such rather than as a plausible zero.
inline core::StateVector nan_state() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {Eigen::Vector3d::Constant(nan), Eigen::Vector3d::Constant(nan)};
}

// Per-epoch score against the truth.
struct EpochScore {
  double t_s = 0.0;
  Eigen::Vector3d relative_position_rtn_m = Eigen::Vector3d::Zero();  // estimate minus truth, centres of mass
  Eigen::Vector3d relative_velocity_rtn_mps = Eigen::Vector3d::Zero();
  // The same position error with the spacecraft's centre-of-mass knowledge error removed: the
  // error of the antennas' relative position, what the GPS measurements determine.
  Eigen::Vector3d relative_antenna_rtn_m = Eigen::Vector3d::Zero();
  double absolute_position_m = 0.0, absolute_velocity_mps = 0.0;  // of the local spacecraft, 3D
  // Receiver clocks, estimate minus truth [m]: the remote one's error relative to the local one
  // moves the remote antenna |v| dt along-track at its reception instant.
  double clock_error_dsc_m = 0.0, clock_error_osc_m = 0.0;
  Eigen::Vector3d empirical_dsc_rtn_mps2 = Eigen::Vector3d::Zero();  // estimated empirical accelerations
  Eigen::Vector3d empirical_osc_rtn_mps2 = Eigen::Vector3d::Zero();
  const char* status = "float";  // fixed, partial, float, outage
  bool wrong_fix = false;
  int satellites = 0, double_differences = 0;
  int graphic_used = 0, graphic_rejected = 0, sdcp_rejected = 0;
  double nis_sum = 0.0;
  int nis_count = 0, detected_slips = 0, ephemeris_switches = 0;
  double graphic_nis_sum = 0.0, sdcp_nis_sum = 0.0;  // their parts of nis_sum (graphic_used, sdcp_used scalars)
  int sdcp_used = 0;
  double step_us = 0.0;
  double nees = 0.0;  // of the antennas' relative position (3 degrees of freedom)
  Eigen::Vector3d antenna_sigma_rtn_m = Eigen::Vector3d::Zero();  // the filter's 1-sigma of that position
  // Observations (run's summary.json): the epoch lies in an observation window, or in a slew to
  // or from one; the relative error of the payload reference points (what the telescope's focal
  // geometry needs: the LRF's end points) along the line of sight and across it [m].
  bool in_observation = false, in_slew = false;
  double payload_los_m = 0.0, payload_lateral_m = 0.0;
  const char* laser = "";  // "used", "rejected" or "" (no range at this epoch, or not fused)
  // With a crosslink delay of L s the epoch's solution is in use L s later: its forecast to then
  // (CdgpsFilter::forecast, plus the commanded impulses of those L s) against the truth then. The
  // epoch's own errors when there is no delay.
  Eigen::Vector3d forecast_antenna_rtn_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d forecast_velocity_rtn_mps = Eigen::Vector3d::Zero();
  // The scored solution's states of both spacecraft (DSC, OSC), GCRF, at the epoch's time tag:
  // the centres of mass, and the antenna phase centres it implies (nav_score.hpp
  // estimated_antenna). NaN when the run has no attitude at the epoch.
  std::array<core::StateVector, 2> com_gcrf = {nan_state(), nan_state()};
  std::array<core::StateVector, 2> antenna_gcrf = {nan_state(), nan_state()};
};

/// One double-difference integer of a full fix (fixes_<craft>.csv): the SD ambiguity (OSC minus
/// DSC) of `prn` minus that of `reference_prn`, L1 [cycles], at t_s [s after the scenario start].
struct FixedDoubleDifference {
  double t_s = 0.0;
  int reference_prn = 0, prn = 0;
  std::int64_t integer_cycles = 0;
};

struct Replay {
  nav::Craft local = nav::Craft::kDsc;
  const char* name = "dsc";
  std::vector<EpochScore> epochs;
  double first_fix_s = -1.0;  // time to first fix after the cold start [s]
  double start_s = -1.0;      // the filter's first epoch [s after the scenario start]
  std::vector<double> impulse_t_s;  // commanded impulses applied [s after the scenario start]
  double latency_s = 0.0;           // the crosslink delay rounded up to whole epochs [s]
  std::vector<FixedDoubleDifference> fixes;  // of every full fix, in time order
  // The receiver's time tags over the replay (truth.csv's epochs up to its end, --duration): an
  // epoch missing from the receiver's file (a data gap) is one of them, counted as not fixed.
  std::vector<double> time_tags_s;
};

/// The self-contained HTML page (inline SVG) of the replays: per filter, the relative position
/// (antennas) and velocity errors in RTN, the estimated empirical accelerations and the
/// ambiguity-resolution status over time (the navigation figures of Guffanti et al., AAS 23-149,
/// 2023, Figs. 13-14), and the
/// summary.
std::string nav_page(const std::string& run_dir, const std::vector<Replay>& replays, const nlohmann::json& summary);

}  // namespace visors::nav_app
