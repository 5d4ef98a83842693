#pragma once
// Reading spherical-harmonic gravity fields from ICGEM `.gfc` files into the flight layer's
// dynamics::GravityField. Ground side (visors_dynamics_files).

#include <filesystem>
#include <string>

#include "visors/core/result.hpp"
#include "visors/dynamics/gravity_field.hpp"

namespace visors::dynamics::files {

/// Reads an ICGEM `.gfc` file (format: ICGEM "Format of the gravity field models" 2.0; the
/// project's files' quirks: docs/algorithms/dynamics.md#reading-icgem-files). `max_degree` >= 0
/// truncates the field to that degree (-1: the file's max_degree). Header keys before
/// `end_of_head`: earth_gravity_constant and radius (required), max_degree (required), norm
/// (absent = fully_normalized; `unnormalized` is converted to fully normalised), tide_system,
/// modelname; other lines (free text such as JGM-3's `J2-DOT ...`) are
/// tolerated. Data lines `gfc n m C S [sigmas ...]` accept e/E/d/D exponents and extra columns.
/// Missing degree-0/1 lines mean C̄00 = 1 and zero degree-1 terms. Time-variable records
/// (gfct, trnd, acos, asin, dot) are rejected: the static field would silently be wrong.
/// Every error names "<file>:<line>" in Error::field (or the file alone) and the problem.
core::Result<GravityField> read_icgem(const std::filesystem::path& file, int max_degree = -1);

/// Finds `name_or_path` through core::files::find_data_file (absolute, existing, or relative to
/// the data search path, e.g. "gravity/GGM05S_d90.gfc") and reads it truncated to `degree` (-1:
/// all). Parsed once per (file, degree) in a process and kept: later calls return a copy.
/// A missing file is an error here: the caller decides whether embedded_gravity_field() is an
/// acceptable fallback (GravityConfig::allow_embedded_fallback) and records that it used it.
core::Result<GravityField> load_gravity_field(const std::string& name_or_path, int degree = -1);

}  // namespace visors::dynamics::files
