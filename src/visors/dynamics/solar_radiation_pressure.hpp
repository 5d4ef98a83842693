#pragma once
// Solar radiation pressure on a flat-plate ("cannonball") spacecraft with a cylindrical Earth
// shadow. Montenbruck & Gill, Satellite Orbits (2000), eq. 3.75 and sec. 3.4.2:
//   a = nu * P_sun * C_R * (A/m) * AU^2 * (r - r_sun) / |r - r_sun|^3,
// which points away from the Sun and scales the pressure with the inverse square of the actual
// Sun distance. nu is the visible fraction of the solar disk:
//  - cylindrical shadow (on board): 0 or 1, a step at the shadow boundary;
//  - conical shadow with penumbra (truth; M&G sec. 3.4.2, eqs. 3.85-3.87): the overlap of the
//    apparent solar and Earth disks, continuous over the ~8-10 s penumbra crossing at 500 km.
//    The continuity matters: a fixed-step RK4 step across a step function makes an O(h) error
//    (~1e-6 m/s per crossing for these spacecraft, ~10 cm of along-track drift per day).

#include <Eigen/Core>

namespace visors::dynamics {

/// Solar radiation pressure at 1 AU, Montenbruck & Gill (2000) eq. 3.69 (1367 W/m^2 / c) [N/m^2].
inline constexpr double kSolarPressureAt1Au = 4.56e-6;
/// Astronomical unit, IAU 2012 Resolution B2 (exact) [m].
inline constexpr double kAstronomicalUnit = 1.495978707e11;

/// Shadow function of a cylindrical Earth of radius `earth_radius` [m]: 0 when the satellite at
/// `r` is behind the Earth as seen from the Sun at `r_sun` (both geocentric, same frame), else 1.
double cylindrical_shadow(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double earth_radius);

/// Conical shadow function with penumbra for a spherical Earth of radius `earth_radius` [m]
/// and a Sun of radius kSunRadius: the visible fraction of the solar disk in [0, 1].
double conical_shadow(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double earth_radius);

/// Solar radius used for the penumbra, Montenbruck & Gill (2000) sec. 3.4.2 [m].
inline constexpr double kSunRadius = 696.0e6;

/// SRP acceleration [m/s^2] for the illumination factor `nu` in [0, 1], pressure `p_1au` [N/m^2],
/// reflectivity coefficient `cr`, area [m^2] and mass [kg]; positions geocentric, same frame [m].
Eigen::Vector3d srp_acceleration(const Eigen::Vector3d& r, const Eigen::Vector3d& r_sun, double nu,
                                 double p_1au, double cr, double area_m2, double mass_kg);

}  // namespace visors::dynamics
