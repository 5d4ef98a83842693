#pragma once
// GPS almanac files, ground side: YUMA (the US Coast Guard NAVCEN text format: one block per
// satellite, "Key: value" lines, angles in radians) and SEM (NAVCEN "System Effectiveness Model"
// format: a two-line header with the week and time of applicability, then per satellite PRN, SVN,
// URA, five lines of three numbers with angles in SEMICIRCLES and the inclination as an offset
// from 0.30 semicircles, health and configuration). Both carry the week modulo 1024: the full
// week is the one nearest `near` (a time the almanac is known to be within 512 weeks of).

#include <filesystem>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/almanac.hpp"

namespace visors::gnss::files {

/// Errors name "<path>:<line>" and the key or field: unknown or missing key, bad number, a
/// truncated block, an implausible entry (validate()).
core::Result<std::vector<GpsAlmanacEntry>> read_yuma_almanac(const std::filesystem::path& path, core::GpsTime near);
core::Result<std::vector<GpsAlmanacEntry>> read_sem_almanac(const std::filesystem::path& path, core::GpsTime near);

}  // namespace visors::gnss::files
