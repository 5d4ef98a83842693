#pragma once
// What `visors nav` reads from a `visors gnss-sim` run directory: the resolved scenario, both
// receivers' observations (RINEX 3: C1C, L1C and its loss-of-lock indicator), the broadcast
// ephemerides (brdc.rnx), and for scoring only the truth: each spacecraft's centre of mass in
// GCRF at the time tag (truth.csv) and each channel's integer ambiguity and receiver phase
// offset (channels_truth.csv), from which the true double-difference integers follow.

#include <array>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include "core/state_vector.hpp"
#include "core/status.hpp"
#include "gnss/ephemeris_set.hpp"
#include "nav/gps_observations.hpp"
#include "sim/campaign_scenario.hpp"

namespace visors::nav_app {

struct ChannelTruth {
  double single_difference_cycles = 0.0;  // ambiguity + receiver phase offset (per receiver)
};

struct RunInputs {
  sim::CampaignScenario scenario;
  std::vector<nav::GpsReceiverEpoch> dsc, osc;  // in time order
  gnss::EphemerisSet ephemerides;
  /// Truth centre of mass at each epoch's time tag [s after the scenario start].
  std::map<long long, std::pair<core::StateVector, core::StateVector>> truth;  // key: ms
  /// Per epoch (ms) and PRN: the receiver's (integer ambiguity + phase offset) [cycles], DSC and OSC.
  std::map<long long, std::map<int, std::pair<double, double>>> phase_truth;
  /// True minus nominal centre of mass, body frame [m], DSC and OSC: the draw gnss-sim made from
  /// the scenario's seed (sim/spacecraft_geometry.hpp). The filter knows only the nominal one.
  std::array<Eigen::Vector3d, 2> com_knowledge_error_body_m{};
};

/// Reads `run_dir`; errors name the file (and line).
core::Result<RunInputs> read_run(const std::filesystem::path& run_dir);

}  // namespace visors::nav_app
