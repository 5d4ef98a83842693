#pragma once
// Control input matrix Gamma of the quasi-nonsingular ROE: d(roe) = Gamma * dv_rtn for an impulse
// dv_rtn [m/s] in the chief's RTN frame at the burn time (Gauss variational equations).
// a * Gamma has units of s.

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"

namespace visors::astro {

using ControlInputMatrix = Eigen::Matrix<double, 6, 3>;

/// Eccentric form, exact in e (first order in dv), including the O(e) terms Lambda_R,
/// Lambda_T of the dlambda row that the commonly published form omits
/// (docs/algorithms/relative-motion.md#control-input-matrix).
/// Chief: its Keplerian elements at the burn (validated, 0 < i < pi).
ControlInputMatrix control_input_matrix(const KeplerianElements& chief, double mu);

/// The commonly published eccentric form without Lambda_R, Lambda_T (for comparison only).
ControlInputMatrix control_input_matrix_without_lambda_terms(const KeplerianElements& chief,
                                                             double mu);

/// Near-circular form (D'Amico), with the chief's mean argument of latitude u = argp + M.
ControlInputMatrix control_input_matrix_near_circular(const KeplerianElements& chief, double mu);

}  // namespace visors::astro
