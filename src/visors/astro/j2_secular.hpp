#pragma once
// Secular first-order J2 rates of the mean elements (Brouwer 1959; e.g. Vallado 4th ed. eqs.
// 9-41/9-42, written with the kappa factor of Koenig, Guffanti & D'Amico 2017, eq. 13) and
// mean-element propagation with them. a, e, i are constant under secular J2.

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"

namespace visors::astro {

struct J2SecularRates {
  double raan_dot = 0.0;  // [rad/s]
  double argp_dot = 0.0;  // [rad/s]
  double M_dot = 0.0;     // includes the Keplerian mean motion n [rad/s]
  double n = 0.0;         // Keplerian mean motion sqrt(mu/a^3) [rad/s]
  double kappa = 0.0;     // (3/4) J2 R^2 sqrt(mu) / (a^(7/2) eta^4) [rad/s]
};

/// Rates of validated mean elements.
J2SecularRates j2_secular_rates(const KeplerianElements& mean,
                                const core::EarthGravityConstants& gravity = {});

/// Mean elements after dt [s]: raan, argp, M advanced linearly (not wrapped).
KeplerianElements propagate_mean_j2(const KeplerianElements& mean, double dt,
                                    const core::EarthGravityConstants& gravity = {});

/// Two-body propagation of the elements (M advanced with n only).
KeplerianElements propagate_kepler(const KeplerianElements& elements, double dt, double mu);

}  // namespace visors::astro
