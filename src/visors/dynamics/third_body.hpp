#pragma once
// Point-mass third-body perturbation on an Earth satellite (Montenbruck & Gill 2000, eq. 3.37):
//   a = GM_b [ (s - r)/|s - r|^3 - s/|s|^3 ],
// s the body's and r the satellite's geocentric positions. The second (indirect) term is the
// body's pull on the Earth. In double precision the cancellation between the two terms leaves
// ~1e-18 m/s^2 at LEO, so Battin's f(q) reformulation is not needed.

#include <Eigen/Core>

namespace visors::dynamics {

/// Heliocentric gravitational constant, IAU 2009 system of astronomical constants (TDB-compatible
/// value, Luzum et al. 2011, Celest. Mech. Dyn. Astr. 110, Table 1) [m^3/s^2].
inline constexpr double kGmSun = 1.32712440041e20;
/// Lunar gravitational constant, GM_earth / 81.30056907 (IAU 2009 mass ratio, Luzum et al. 2011)
/// with GM_earth = 3.986004418e14 [m^3/s^2].
inline constexpr double kGmMoon = 3.986004418e14 / 81.30056907;

/// Acceleration [m/s^2] of the satellite at `r` by a body of constant `gm` [m^3/s^2] at `s`
/// (both geocentric, same frame [m]).
Eigen::Vector3d third_body_acceleration(const Eigen::Vector3d& r, const Eigen::Vector3d& s, double gm);

}  // namespace visors::dynamics
