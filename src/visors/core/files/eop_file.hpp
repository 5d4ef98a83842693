#pragma once
// Reading Earth orientation parameters from an IERS finals2000A file (Bulletin A columns; format:
// USNO readme.finals2000A) into the flight layer's core::EopTable. Ground side (visors_core_files).

#include <filesystem>

#include "visors/core/eop.hpp"
#include "visors/core/result.hpp"

namespace visors::core::files {

/// Parses a finals2000A file. Rows must be consecutive days; rows without polar motion or
/// UT1-UTC are accepted only at the end (future dates) and are dropped. Blank LOD, dX, dY
/// (optional in the format) read as 0. A malformed row is an error naming its line number.
Result<EopTable> read_eop_file(const std::filesystem::path& path);

}  // namespace visors::core::files
