#pragma once
// Reading the NRLMSISE-00 coefficient tables (data/atmosphere/nrlmsise00_coefficients.txt, its
// provenance in data/SOURCES.md) into the flight layer's dynamics::Nrlmsise00Coefficients. Ground
// side (visors_dynamics_files).
//
// Format (the file's header): '#' comment lines and blank lines are ignored; each table is a line
// "array NAME ROWS COLS" followed by ROWS lines of COLS numbers (row-major, 0-based as in
// Nrlmsise00Coefficients). The ten tables pt 1x150, pd 9x150, ps 1x150, pdl 2x25, ptm 1x10,
// pdm 8x10, ptl 4x100, pma 10x100, sam 1x100, pavgm 1x10 must each appear once, in any order,
// with exactly those sizes.

#include <filesystem>
#include <string_view>

#include "visors/core/result.hpp"
#include "visors/dynamics/nrlmsise00_coefficients.hpp"

namespace visors::dynamics::files {

/// Parses the file at `path`. Errors: the file cannot be opened (field ""); a malformed line, an
/// unknown, repeated or wrongly sized table, a row with the wrong count of numbers, a token that
/// is not a finite number, a table cut short by the next header (field "line N", the message
/// names the table, row and column); a table missing or cut short by the end of the file (field
/// the table's name); then nrlmsise00_coefficients_problem (field the entry, "pd[3][0]").
core::Result<Nrlmsise00Coefficients> read_nrlmsise00_coefficients(const std::filesystem::path& path);

/// The same from the file's text (`source` names it in messages).
core::Result<Nrlmsise00Coefficients> parse_nrlmsise00_coefficients(std::string_view text, std::string_view source);

}  // namespace visors::dynamics::files
