#pragma once
// The navigation filter's tunables (nav/cdgps_settings.hpp) from TOML (ground side): a [nav]
// table whose keys are CdgpsSettings' field names, and [nav.acceptance] for the integer
// resolution's (min_success_rate, min_ratio, partial, min_partial). Every key optional: absent
// ones keep the values `settings` already holds. Unknown keys, wrong types and values that
// nav::check refuses are errors naming "nav.<key>". `local` is not a tunable (the replay runs
// one filter per spacecraft).

#include <toml++/toml.h>

#include "visors/core/result.hpp"
#include "visors/nav/cdgps_settings.hpp"

namespace visors::config {

/// Reads root["nav"] into `settings` (left unchanged on error).
core::Result<bool> read_cdgps_settings(const toml::table& root, nav::CdgpsSettings& settings);

}  // namespace visors::config
