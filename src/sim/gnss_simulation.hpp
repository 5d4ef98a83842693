#pragma once
// `visors gnss-sim`: raw GPS measurements of both spacecraft along the scenario's truth orbits
// (formation flying freely: no control), for testing navigation filters and for processing with
// other GNSS software.
//
// The world: the scenario's truth force model (RK4 at integration_step_s) for both spacecraft from
// their initial states; attitude nominal (antenna at the zenith) or observation (payload +X at the
// Sun), [gnss] attitude; the true centre of mass drawn as in `visors run` (same seed, same
// geometry); the GPS constellation of [gnss] nav_file moved to the scenario start
// (gnss/constellation.hpp) with broadcast errors (sim/gps_satellite_truth.hpp); one receiver per
// spacecraft (sim/gps_receiver.hpp) with the navigation file's Klobuchar coefficients as the truth
// ionosphere. Earth orientation: the force model's EOP file when it names one, else zero EOP
// (both the receiver geometry and the truth ITRF use the same).
//
// Output directory: scenario.toml (resolved), dsc.rnx and osc.rnx (RINEX 3.05 observations,
// C1C L1C D1C S1C, LLI bit 0 on loss of lock), brdc.rnx (RINEX 3.05 navigation: the broadcast
// ephemerides the receivers decode, i.e. with the broadcast errors), truth.csv (per epoch and
// spacecraft: centre of mass GCRF, antenna phase centre ITRF, receiver clock) and
// channels_truth.csv (per epoch, spacecraft and channel: the true range, satellite clock,
// ionosphere, integer ambiguity and phase offsets), summary.json.

#include <filesystem>
#include <functional>

#include <nlohmann/json.hpp>

#include "core/status.hpp"
#include "sim/campaign_scenario.hpp"
#include "sim/campaign_simulation.hpp"

namespace visors::sim {

struct GnssRunResult {
  nlohmann::json summary;
  std::filesystem::path dir;
};

/// Runs [gnss] duration_s of the scenario at its step_s. Errors: set-up (named field), files.
core::Result<GnssRunResult> run_gnss_simulation(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                                const std::function<void(const RunProgress&)>& progress = {});

}  // namespace visors::sim
