#pragma once
// Quasi-nonsingular elements (docs/conventions.md): a, u = argp + M, ex = e cos argp,
// ey = e sin argp, i, raan. Nonsingular for e -> 0 (singular only for i -> 0, where raan is).

#include "visors/astro/keplerian_elements.hpp"

namespace visors::astro {

struct QuasiNonsingularElements {
  double a = 0.0;     // [m]
  double u = 0.0;     // mean argument of latitude argp + M [rad]
  double ex = 0.0;    // e cos argp [-]
  double ey = 0.0;    // e sin argp [-]
  double i = 0.0;     // [rad]
  double raan = 0.0;  // [rad]
};

/// u = argp + M without wrapping (keeps the revolution count of M).
QuasiNonsingularElements quasi_nonsingular_from_keplerian(const KeplerianElements& elements);

/// argp = atan2(ey, ex) (0 when ex = ey = 0, the circular convention of keplerian_elements.hpp),
/// M = u - argp. Unchecked: e = hypot(ex, ey) < 1 is the caller's precondition.
KeplerianElements keplerian_from_quasi_nonsingular(const QuasiNonsingularElements& elements);

}  // namespace visors::astro
