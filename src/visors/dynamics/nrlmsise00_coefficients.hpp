#pragma once
// The coefficient tables of the NRLMSISE-00 neutral-atmosphere model (Picone, Hedin, Drob &
// Aikin, "NRLMSISE-00 empirical model of the atmosphere: Statistical comparisons and scientific
// issues", J. Geophys. Res. 107(A12), 1468, 2002), as plain fixed-size data built on the ground
// (dynamics/files/nrlmsise00_file.hpp reads them from data/atmosphere/nrlmsise00_coefficients.txt).
//
// The names and the 0-based index layout are those of the data file (its header; the C port's
// arrays): the FORTRAN PD(i, j) is pd[j-1][i-1]. What each table holds (Hedin 1987, "MSIS-86
// thermospheric model", JGR 92(A5) 4649, appendix; Picone et al. 2002):
//   pt     the expansion G(L) of the exospheric temperature T_inf;
//   pd     one expansion per density at z_lb: rows He, O, N2, T_lb (the temperature at z_lb),
//          O2, Ar, H, N, anomalous O;
//   ps     the expansion of the temperature gradient at z_lb;
//   pdl    turbopause, chemistry and dissociation parameters (2 rows);
//   ptm    scalars of the temperature profile (ptm[0] T_inf, ptm[1] T_lb, ptm[5] z_lb, ...);
//   pdm    per density (He, O, N2, O2, Ar, H, N, anomalous O): the density at z_lb, the mixing
//          ratio at the ground, turbopause and correction heights;
//   ptl    the lower-thermosphere temperature nodes (110, 100, 90, 72.5 km);
//   pma    the middle-atmosphere temperature nodes and end gradients (72.5 km to the ground);
//   sam    not used by the model (kept because the data file has it);
//   pavgm  the mean middle-atmosphere temperatures at the nodes.

#include <array>
#include <optional>

#include "visors/core/result.hpp"

namespace visors::dynamics {

struct Nrlmsise00Coefficients {
  std::array<double, 150> pt{};
  std::array<std::array<double, 150>, 9> pd{};
  std::array<double, 150> ps{};
  std::array<std::array<double, 25>, 2> pdl{};
  std::array<double, 10> ptm{};
  std::array<std::array<double, 10>, 8> pdm{};
  std::array<std::array<double, 100>, 4> ptl{};
  std::array<std::array<double, 100>, 10> pma{};
  std::array<double, 100> sam{};
  std::array<double, 10> pavgm{};
};

/// The problem of a set of tables, or nullopt when it can be used: every value finite; the
/// parameter-set marker (index 99) of every ptl and pma row 0 or 2 (the published lower-atmosphere
/// expansion accepts no other set); the heights z_lb = ptm[5] and z_a = pdl[1][15] with
/// 110 km < z_a and z_lb <= z_a (the spline's first node is z_a, above the 110 km node); the
/// temperatures ptm[0] pt[0], ptm[1] pd[3][0] and the node temperatures > 0. Errors name the
/// table and index, e.g. "pd[3][51]".
std::optional<core::Error> nrlmsise00_coefficients_problem(const Nrlmsise00Coefficients& c);

}  // namespace visors::dynamics
