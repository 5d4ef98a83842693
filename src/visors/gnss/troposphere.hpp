#pragma once
// Tropospheric delay of a GROUND receiver (non-dispersive: code and carrier are both delayed by
// it): Saastamoinen's zenith delays over a standard atmosphere, mapped to the satellite's
// elevation. No surface meteorology is needed; the model is good to a few cm in the zenith (the
// weather's departure from the standard atmosphere, mostly in the wet part, dominates).
//
// Standard atmosphere at the receiver (all three from the height alone):
//   temperature T = 288.15 K - 6.5e-3 K/m * H, pressure p = 1013.25 hPa * (T / 288.15 K)^5.25588,
//     U.S. Standard Atmosphere 1976 (NOAA/NASA/USAF), part 1, eqs. 23 (T) and 33a (p) for the
//     lowest layer; the exponent is g0 M0 / (R* L) with the document's constants (g0 = 9.80665 m/s^2,
//     M0 = 28.9644 kg/kmol, R* = 8.31432 J/(mol K), L = 6.5e-3 K/m). H is the geopotential
//     height, H = r0 h / (r0 + h) with r0 = 6356.766 km (eq. 18). Written out this is the
//     p = 1013.25 (1 - 2.25577e-5 H)^5.25588 hPa used with Saastamoinen by RTKLIB (which has the
//     exponent as 5.2568, 273.16 K for 0 degC and the geometric height; none matters at 1 mm);
//   water-vapour pressure e = RH * e_s(T), e_s = 6.1078 hPa * exp(17.27 t / (t + 237.3 degC)) with
//     t = T - 273.15 K: the Magnus-type formula of Tetens (1930) with the constants of Murray
//     (1967), J. Appl. Meteor. 6, 203-204 (saturation over water); RH is a setting (0.7 default).
// The height is taken as above the ellipsoid (the geoid undulation, <= ~100 m, is ignored: 100 m
// is ~1.2 % of the pressure, ~3 cm of zenith delay).
//
// Zenith delays, Saastamoinen (1972), "Atmospheric correction for the troposphere and
// stratosphere in radio ranging of satellites", Geophys. Monogr. 15, AGU, with the constant of
// Davis et al. (1985), Radio Science 20(6), 1593-1607 (0.0022768 +- 0.0000005 m/hPa):
//   ZHD = 0.0022768 m/hPa * p / (1 - 0.00266 cos 2phi - 0.00028 /km * h)
//   ZWD = 0.0022768 m/hPa * (1255 K / T + 0.05) * e.
//
// Mapping to the elevation E, both available (TroposphereMapping):
//   kNiell1996 (default): Niell (1996), "Global mapping functions for the atmosphere delay at radio
//     wavelengths", J. Geophys. Res. 101(B2), 3227-3246: the continued fraction of Marini (1972)
//     normalised to 1 at the zenith, with the coefficient tables (Table 3: hydrostatic
//     average and seasonal amplitude at 15..75 deg latitude, height correction; wet), linear in
//     latitude between the tabulated rows, a seasonal cosine with phase day-of-year 28 (half a
//     year later in the southern hemisphere). It needs only latitude, height and the day of year.
//   kCosecant: 1 / cos z = 1 / sin E for both parts, the flat-Earth mapping used by RTKLIB's
//     tropmodel(). It ignores the Earth's curvature: too large by ~1 % at 15 deg, ~13 % (~3 m) at
//     5 deg elevation.
// Niell is the default: it was fitted to ray traces through radiosonde profiles down to 3 deg
// elevation and costs about the same, while 1/sin E is metres off at low elevation, where a
// ground receiver still tracks satellites (tests: 10.16 / 10.75 published at 5 deg against
// 1/sin 5 deg = 11.47).
//
// Valid heights: -500 m .. 10 km (the standard atmosphere's lowest layer ends at 11 km; the
// Saastamoinen model is meant for ground stations). Elevations: (0, pi/2] rad; both mappings grow
// as 1/sin E at the horizon and Niell's tables were fitted down to 3 deg.

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

namespace visors::gnss {

enum class TroposphereMapping {
  kNiell1996,  // Niell (1996) hydrostatic and wet mapping functions (default)
  kCosecant,   // 1 / sin(elevation) for both parts, as in RTKLIB's tropmodel()
};

struct TroposphereSettings {
  double relative_humidity = 0.7;  // of the standard atmosphere at the receiver, [0, 1]
  TroposphereMapping mapping = TroposphereMapping::kNiell1996;
};

/// The standard atmosphere at the receiver (see the file comment).
struct StandardAtmosphere {
  double pressure_hpa = 0.0;
  double temperature_k = 0.0;
  double water_vapour_pressure_hpa = 0.0;
};

struct ZenithDelays {
  double hydrostatic_m = 0.0;
  double wet_m = 0.0;
  [[nodiscard]] double total_m() const { return hydrostatic_m + wet_m; }
};

struct MappingFactors {
  double hydrostatic = 0.0;  // slant / zenith hydrostatic delay [-]
  double wet = 0.0;          // slant / zenith wet delay [-]
};

/// Errors name the field: "height_m" non-finite or outside [-500, 10000] m, "relative_humidity"
/// outside [0, 1] (or NaN).
core::Result<StandardAtmosphere> standard_atmosphere(double height_m, double relative_humidity = 0.7);

/// Saastamoinen zenith hydrostatic and wet delays [m] at geodetic latitude [rad] and height [m]
/// above the ellipsoid. Errors name the field: "latitude" non-finite or outside [-pi/2, pi/2], and
/// those of standard_atmosphere().
core::Result<ZenithDelays> saastamoinen_zenith_delays_m(double latitude_rad, double height_m,
                                                        const TroposphereSettings& settings = {});

/// Niell (1996) mapping factors at geodetic latitude [rad], height [m], elevation [rad] and GPS
/// time t (its calendar day of year drives the hydrostatic seasonal term). Errors name the field:
/// "latitude", "height_m" (as above), "elevation" non-finite or outside (0, pi/2].
core::Result<MappingFactors> niell_mapping(double latitude_rad, double height_m, double elevation_rad,
                                           core::GpsTime t);

/// Slant tropospheric delay [m]: ZHD * m_h + ZWD * m_w with the settings' mapping. t matters only
/// for the Niell mapping; pass the observation time: the seasonal term moves the delay at 45 deg
/// latitude, sea level, by up to 0.6 cm at 15 deg, 1.9 cm at 10 deg and 11 cm at 5 deg elevation
/// over the year (the default, the GPS epoch, is day 6, near the northern winter extreme).
/// Errors as the functions above.
core::Result<double> saastamoinen_delay_m(double latitude_rad, double height_m, double elevation_rad,
                                          const TroposphereSettings& settings = {}, core::GpsTime t = {});

}  // namespace visors::gnss
