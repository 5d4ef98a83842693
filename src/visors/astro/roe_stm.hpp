#pragma once
// State transition matrices of MEAN quasi-nonsingular ROE: roe(t0 + tau) = phi * roe(t0).
// The chief elements are its MEAN Keplerian elements at t0 (the start of the interval); the
// matrix is built in closed form from them, so do not chain short steps expecting an exact
// match to one long step (the e-coupling terms are evaluated at each step's chief).
// Equations and a worked example: docs/algorithms/relative-motion.md#state-transition-matrices.

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/constants.hpp"

namespace visors::astro {

using RoeStm = Eigen::Matrix<double, 6, 6>;

/// Two-body: identity plus phi(dlambda, da) = -1.5 n tau (any e).
RoeStm keplerian_roe_stm(const KeplerianElements& chief_mean, double tau, double mu);

/// Secular J2: Koenig, Guffanti & D'Amico, JGCD 40(7) 2017, App. A eq. (A6), with
/// omega_f = omega_i + omegadot tau. It is the exact Jacobian, at roe = 0, of propagating chief
/// and deputy mean elements with the secular rates of j2_secular.hpp and differencing exactly.
RoeStm j2_roe_stm(const KeplerianElements& chief_mean, double tau,
                  const core::EarthGravityConstants& gravity = {});

}  // namespace visors::astro
