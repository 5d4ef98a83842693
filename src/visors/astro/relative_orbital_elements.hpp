#pragma once
// Quasi-nonsingular relative orbital elements (D'Amico; docs/conventions.md), deputy relative to
// chief, exact nonlinear definition:
//   da = (a_d - a_c)/a_c, dlambda = (u_d - u_c) + (raan_d - raan_c) cos i_c,
//   dex = ex_d - ex_c, dey = ey_d - ey_c, dix = i_d - i_c, diy = (raan_d - raan_c) sin i_c,
// with u = argp + M, differences of angles wrapped to (-pi, pi]. Dimensionless.

#include <Eigen/Core>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/core/status.hpp"

namespace visors::astro {

using RelativeOrbitalElements = Eigen::Matrix<double, 6, 1>;

/// Named indices into RelativeOrbitalElements (and the rows/columns of ROE matrices).
namespace roe {
inline constexpr int kDa = 0;
inline constexpr int kDlambda = 1;
inline constexpr int kDex = 2;
inline constexpr int kDey = 3;
inline constexpr int kDix = 4;
inline constexpr int kDiy = 5;
}  // namespace roe

/// ROE of a deputy w.r.t. a chief. Both element sets are validated (field "chief.a", "deputy.e",
/// ...); the chief must not be equatorial ("chief.i": sin i_c = 0 makes diy meaningless).
core::Outcome<RelativeOrbitalElements> roe_from_keplerian(const KeplerianElements& chief,
                                                         const KeplerianElements& deputy);

/// Inverse of roe_from_keplerian: the deputy's elements. Rejects a non-equatorial chief as above,
/// non-finite ROE ("roe"), da <= -1 ("roe.da") and a deputy eccentricity >= 1 ("roe.dex").
/// The deputy's argp is 0 when its eccentricity is exactly 0; angles are not wrapped.
core::Outcome<KeplerianElements> deputy_from_roe(const KeplerianElements& chief,
                                                const RelativeOrbitalElements& roe);

}  // namespace visors::astro
