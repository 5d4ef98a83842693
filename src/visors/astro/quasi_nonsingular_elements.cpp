#include "visors/astro/quasi_nonsingular_elements.hpp"

#include <cmath>

namespace visors::astro {

QuasiNonsingularElements quasi_nonsingular_from_keplerian(const KeplerianElements& el) {
  return QuasiNonsingularElements{el.a,
                                  el.argp + el.M,
                                  el.e * std::cos(el.argp),
                                  el.e * std::sin(el.argp),
                                  el.i,
                                  el.raan};
}

KeplerianElements keplerian_from_quasi_nonsingular(const QuasiNonsingularElements& q) {
  const double e = std::hypot(q.ex, q.ey);
  const double argp = e > 0.0 ? std::atan2(q.ey, q.ex) : 0.0;
  return KeplerianElements{q.a, e, q.i, q.raan, argp, q.u - argp};
}

}  // namespace visors::astro
