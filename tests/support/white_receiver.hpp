#pragma once
// The white-noise receiver of the earlier, friendlier truth (no elevation dependence, no
// multipath), for the tests of machinery whose figures assume it: fault handling, RINEX round
// trips, the closed loop's navigation plumbing. The real sky's figures (the default scenarios)
// are measured by the commands of docs/results.md; docs/truth-and-knowledge.md.

#include <string>
#include <utility>

#include <gtest/gtest.h>

#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/gps_receiver.hpp"

namespace visors::test {

inline void use_white_receiver(sim::GpsReceiverSettings& receiver) {
  receiver.elevation_dependent_noise = false;
  receiver.code_multipath_m = 0.0;
  receiver.phase_multipath_m = 0.0;
}

/// What a flight team that knows its receiver white tells its filter (a scenario without a [nav]
/// table): no multipath states and no code multipath, which the flight defaults give for the real
/// sky's (nav/cdgps_settings.hpp).
inline void tell_the_filter_white(sim::CampaignScenario& scenario) {
  EXPECT_TRUE(scenario.nav_toml.empty()) << scenario.nav_toml;
  scenario.nav_toml = "[nav]\nsdcp_multipath_sigma_m = 0.0\ncode_multipath_sigma_m = 0.0\n";
}

/// The same as a [gnss.receiver] table (for scenario texts without one).
inline const std::string kWhiteReceiverToml =
    "[gnss.receiver]\nelevation_dependent_noise = false\ncode_multipath_m = 0.0\nphase_multipath_m = 0.0\n";

/// The shipped gnss_sim.toml's real-sky receiver lines turned white (for tests that edit it).
inline void whiten_shipped_receiver(std::string& text) {
  for (const auto& [from, to] : {std::pair<std::string, std::string>{"elevation_dependent_noise = true", "elevation_dependent_noise = false"},
                                 {"code_multipath_m = 0.3", "code_multipath_m = 0.0"},
                                 {"phase_multipath_m = 0.002", "phase_multipath_m = 0.0"}}) {
    const auto at = text.find(from);
    if (at == std::string::npos) {
      ADD_FAILURE() << "the shipped receiver has no line '" << from << "'";
      continue;
    }
    text.replace(at, from.size(), to);
  }
}

}  // namespace visors::test
