#pragma once
// The linear model every planner, the buffer and the MPC share: mean ROE under the secular-J2
// STM with impulses entering through the eccentric control input matrix,
//     roe(t_ref) = Phi(t_ref, t0) roe(t0) + sum_k Phi(t_ref, t_k) Gamma(t_k) dv_k,
// with Phi(t_ref, t_k) = j2_roe_stm(chief(t_k), t_ref - t_k) (Koenig, Guffanti & D'Amico 2017, A6)
// and Gamma(t_k) = control_input_matrix(chief(t_k)) (GVE, eccentric, with the Lambda terms), the
// chief's mean elements at t_k from secular J2 (astro::propagate_mean_j2);
// docs/algorithms/control.md#the-linear-model.

#include <vector>

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/control/impulse.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/status.hpp"

namespace visors::control {

/// Phi(t_ref, t) Gamma(t): mean-ROE change at t_ref per unit dv_rtn at t [s/m]. Times in s since
/// the epoch of `chief_mean_t0`; t_ref >= t is not required (the STM runs backwards too).
Eigen::Matrix<double, 6, 3> impulse_effect(const astro::KeplerianElements& chief_mean_t0, double t, double t_ref,
                                           const core::EarthGravityConstants& gravity = {});

/// roe(t_ref) from roe(0) and the impulses (any order) [-].
astro::RelativeOrbitalElements predict_roe(const astro::KeplerianElements& chief_mean_t0,
                                           const astro::RelativeOrbitalElements& roe0,
                                           const std::vector<Impulse>& impulses, double t_ref,
                                           const core::EarthGravityConstants& gravity = {});

/// Checks a chief for the near-circular planners (valid elements, e < 0.1, not equatorial) and the
/// gravity constants; the error names a field under `chief_name` (e.g. "chief.e") or "gravity".
core::Status validate_planner_chief(const astro::KeplerianElements& chief, const char* chief_name,
                                    const core::EarthGravityConstants& gravity);

/// Largest |dROE| component the first-order model is used for (a*dROE ~ 69 km at 500 km; the
/// model's errors grow as |dROE|^2 a, i.e. metres at 1e-3).
inline constexpr double kMaxLinearRoe = 1e-2;

/// Finite and within kMaxLinearRoe; the error names `name`.
core::Status validate_roe(const astro::RelativeOrbitalElements& roe, const char* name);

}  // namespace visors::control
