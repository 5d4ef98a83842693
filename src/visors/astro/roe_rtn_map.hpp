#pragma once
// First-order maps between quasi-nonsingular ROE and the relative state in the chief's RTN frame
// (position [m]; velocity [m/s] as the time derivative seen in the rotating RTN frame).
//
// The chief elements are its Keplerian elements at the evaluation time t (osculating for an
// osculating ROE, mean for a mean ROE: the map does not mix them). tau = t - t0 is the time since
// the epoch of the ROE: a ROE given at t0 drifts Keplerian-ly, dlambda(t) = dlambda(t0)
// - 1.5 n tau da, and the tau terms of the map are exactly that drift. Pass tau = 0 when the
// ROE is already at t.
//
// Eccentric form: exact in e, first order in the ROE (after Sullivan, Grimberg & D'Amico, JGCD
// 40(8) 2017; its T-velocity dex/dey entries re-derived, see the .cpp), error O(|roe|^2) a.
// Near-circular form: D'Amico's (2010 thesis) e = 0 map, error O(e |roe|) a in addition
// (decimetres at e = 0.004, 100 m separation). Equations and a worked example:
// docs/algorithms/relative-motion.md#eccentric-roe-to-rtn-map.

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"

namespace visors::astro {

/// 6x6: [r_rtn; v_rtn] = matrix * roe. Columns in the roe:: index order.
using RoeToRtnMatrix = Eigen::Matrix<double, 6, 6>;
/// [r_rtn (m); v_rtn (m/s)].
using RelativeRtnVector = Eigen::Matrix<double, 6, 1>;

/// Eccentric-chief map (validated chief, 0 < i < pi). tau in [s].
RoeToRtnMatrix roe_to_rtn_matrix(const KeplerianElements& chief, double mu, double tau = 0.0);
/// Near-circular map (D'Amico); uses the chief's mean argument of latitude u = argp + M.
RoeToRtnMatrix roe_to_rtn_matrix_near_circular(const KeplerianElements& chief, double mu,
                                               double tau = 0.0);

RelativeRtnVector rtn_from_roe(const KeplerianElements& chief, const RelativeOrbitalElements& roe,
                              double mu, double tau = 0.0);
/// Inverse of rtn_from_roe (solves the 6x6 system, LU with partial pivoting).
RelativeOrbitalElements roe_from_rtn(const KeplerianElements& chief,
                                     const RelativeRtnVector& state_rtn, double mu,
                                     double tau = 0.0);

RelativeRtnVector rtn_from_roe_near_circular(const KeplerianElements& chief,
                                            const RelativeOrbitalElements& roe, double mu,
                                            double tau = 0.0);

}  // namespace visors::astro
