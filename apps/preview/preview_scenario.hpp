#pragma once
// The scenario of `visors preview`: a chief orbit (mean elements), one or more deputy relative
// orbits (mean ROE in metres), a duration and an output step. Read from TOML, validated, SI.

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

namespace visors::preview {

struct FormationSpec {
  std::string name;
  std::array<double, 6> roe_m{};  // a*[da, dlambda, dex, dey, dix, diy], mean [m]
};

struct PreviewScenario {
  core::GpsTime epoch;
  astro::KeplerianElements chief_mean;  // at epoch [m, rad]
  core::EarthGravityConstants earth;
  double orbits = 3.0;       // preview length [chief Keplerian periods]
  double step_s = 10.0;      // output step [s]
  std::optional<std::string> eop_file;  // found through the data search path
  std::vector<FormationSpec> formations;
};

/// Parses and validates a scenario; every error names the TOML key (e.g. "chief.e").
core::Result<PreviewScenario> parse_preview_scenario(const std::string& toml_text);
core::Result<PreviewScenario> load_preview_scenario(const std::filesystem::path& path);

}  // namespace visors::preview
