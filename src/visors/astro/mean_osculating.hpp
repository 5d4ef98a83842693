#pragma once
// First-order J2 map between Brouwer mean and osculating elements.
//
// Theory: Brouwer (1959) first-order short- and long-period J2 terms in Lyddane's (1963) form,
// as written in Schaub & Junkins, "Analytical Mechanics of Space Systems", App. F (eqs.
// F.1-F.22), with one term of F.11 restored (the O(e J2) remainder
// gamma2' e eta^2 X / (4 (1 + eta)) of the short-period l + g; see mean_osculating.cpp).
// Lyddane's form reassembles e, M and i, RAAN through (e + de) sin M + e dM cos M and the like,
// so the map has no 1/e singularity: it is evaluated for any 0 <= e < 1, and the osculating ->
// mean inverse is iterated in the quasi-nonsingular elements (a, u, ex, ey, i, RAAN), which
// stays well conditioned as e -> 0. Remaining singularities: i = 0, pi (RAAN) and the critical
// inclination 1 - 5 cos^2 i = 0 (63.4 and 116.6 deg; long-period terms), both rejected.
//
// Accuracy: the theory's truncation is O(J2^2) a, i.e. metres to tens of metres in a for LEO
// (measured against a numerical J2-only integration in tests/astro/test_mean_osculating.cpp).
// The inverse is converged to round-off (mean -> osc -> mean agrees to ~1e-15).
// Notes: docs/algorithms/relative-motion.md#mean-and-osculating-elements.

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::astro {

/// Osculating elements of mean elements. Rejects invalid elements and the singularities above
/// (field "i"), and e > 0.9 ("e", outside the range the first-order theory is meant for).
core::Outcome<KeplerianElements> osculating_from_mean(const KeplerianElements& mean,
                                                     const core::EarthGravityConstants& gravity = {});

/// Mean elements of osculating elements: fixed-point iteration of the mean -> osculating map in
/// quasi-nonsingular elements until the residual is at round-off. Same rejections, plus
/// "did not converge" (field "osculating") if 50 iterations are not enough.
core::Outcome<KeplerianElements> mean_from_osculating(const KeplerianElements& osculating,
                                                     const core::EarthGravityConstants& gravity = {});

}  // namespace visors::astro
