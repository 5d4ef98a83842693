#pragma once
// Test support: the J2-only numerical "truth" the control tests check the linear model against.

#include <vector>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"

namespace visors::control::test {

/// Terminal MEAN ROE after `tf` [s] of chief (no burns) and deputy (roe0 at t0 plus the impulses,
/// RTN) propagated numerically from mean elements at t0 with the J2-only force model and the
/// Dormand-Prince 8(7) reference integrator; mean <-> osculating by the first-order
/// Brouwer-Lyddane map of astro/mean_osculating.hpp.
astro::RelativeOrbitalElements propagate_j2_numerically(const astro::KeplerianElements& chief_mean0,
                                                        const astro::RelativeOrbitalElements& roe0,
                                                        const std::vector<Impulse>& impulses, double tf);

}  // namespace visors::control::test
