#pragma once
// NRLMSISE-00 neutral atmosphere (Picone, Hedin, Drob & Aikin, J. Geophys. Res. 107(A12), 1468,
// 2002), the MSIS-86 / MSISE-90 formulation (Hedin, JGR 92(A5) 4649, 1987, appendix equations;
// Hedin, JGR 96(A2) 1159, 1991) with the NRLMSISE-00 coefficients (nrlmsise00_coefficients.hpp).
// Equations and conventions as published with the model (the NRL distribution's gtd7/gtd7d);
// the code is this project's own.
//
// What it computes (the published gtd7 with every switch on, output in SI):
//   * above 72.5 km the thermosphere: a Bates-Walker temperature profile
//       T(z) = T_inf - (T_inf - T_lb) exp(-sigma zeta(z, z_lb)),  zeta = (z - z_lb)(R + z_lb)/(R + z)
//     down to z_a = 123.435 km, a cubic spline of 1/T in zeta below it (nodes 110, 100, 90,
//     72.5 km); each species in diffusive equilibrium from its density at z_lb = 120 km, blended
//     with the fully mixed profile below its turbopause, times chemistry/dissociation
//     corrections; T_inf, T_lb, the gradient and the densities at z_lb are each
//     exp or (1 + G(L)) of a spherical-harmonic expansion G(L) in latitude, local time, day of
//     year, UT, longitude, F10.7 and Ap (Hedin 1987 appendix; eq. A22 the expansion);
//   * below 72.5 km a spline temperature profile of the middle atmosphere (nodes 72.5 ... 0 km)
//     and hydrostatic, fully mixed densities joined linearly to the thermosphere above 62.5 km.
//
// Inputs, in the published model's conventions:
//   * day of year (the year is ignored), UT seconds of the day;
//   * geodetic height [km], geodetic latitude and longitude [deg];
//   * local solar time [h], an independent input: the model's documentation gives
//     lst = UT/3600 + longitude/15 (mean solar time, no equation of time) for consistency, and
//     density() uses exactly that, unwrapped (longitude in (-180, 180] deg gives lst in
//     (-12, 36) h; the model's hour angle 0.2618 rad/h makes lst and lst + 24 differ by 1.5e-5
//     rad, so the density jumps by up to 1.3e-5 relative across longitude 180 deg: measured at
//     500 km, October 2024 activity; negligible for drag);
//   * f107: the observed F10.7 of the previous day, f107a: its 81-day centred mean (both at the
//     Earth's distance, not adjusted to 1 AU), ap: the daily Ap;
//   * geomagnetic mode: when SolarActivity::ap_history is present the model runs in its
//     ap-history mode (the published switch 9 = -1: Hedin 1987 eq. A24a-d, a decaying weighted
//     history of the 3-hourly ap), otherwise in the daily-Ap mode (switch 9 = 1). The daily Ap
//     is part of the history array (its element 0) but that mode does not use it.
//
// Outputs: the number densities of He, O, N2, O2, Ar, H, N and anomalous O, the exospheric
// temperature and the temperature at the height, and two total mass densities:
//   * mass_density: gtd7's total, which EXCLUDES anomalous oxygen (the published test values'
//     d[5]);
//   * mass_density_with_anomalous_o: gtd7d's "effective total mass density for drag", which adds
//     16 amu times the anomalous-O density. Anomalous O (hot O and O+ above ~500 km, Picone et al.
//     2002) was fitted to satellite drag data, so this is the density that reproduces
//     drag; density() returns it (docs/nrlmsise00.md compares the two).
//
// The model's own numerical constants are used as published (degrees to radians 1.74533e-2,
// day to radians 1.72142e-2, hour 0.2618, second 7.2722e-5, gas constant 831.4, amu 1.66e-24 g);
// using exact values instead changes the 6th-7th significant digit.
//
// Range: density() answers heights 0 to 1000 km (the published test cases' span) and returns 0
// outside, and for non-finite positions. evaluate() checks its inputs and names the field.
//
// Cost: everything that depends only on the day of year and the activity is kept from the
// previous call (a cache keyed by those inputs: the force model refreshes them once per day or
// per 3-hour ap interval), so a call evaluates only the position- and time-dependent terms
// (docs/nrlmsise00.md gives the measured cost). The cache makes a Nrlmsise00Atmosphere
// single-threaded, like the ForceModel that owns it.

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

#include "visors/core/result.hpp"
#include "visors/dynamics/atmosphere.hpp"
#include "visors/dynamics/nrlmsise00_coefficients.hpp"

namespace visors::dynamics {

/// Inputs of one evaluation, in the model's units and conventions (file comment).
struct Nrlmsise00Input {
  int day_of_year = 1;              // UTC day of year, 1..366
  double ut_seconds = 0.0;          // UT seconds of the day [s], [0, 86400]
  double altitude_km = 0.0;         // geodetic height [km], [0, 1000]
  double latitude_deg = 0.0;        // geodetic latitude [deg], [-90, 90]
  double longitude_deg = 0.0;       // geodetic longitude [deg], [-360, 360]
  double local_solar_time_h = 0.0;  // local solar time [h], [-48, 48]
  SolarActivity activity;           // f107 (previous day), f107a, ap, optional ap_history
};

struct Nrlmsise00Output {
  // Number densities [1/m^3].
  double he = 0.0;
  double o = 0.0;
  double n2 = 0.0;
  double o2 = 0.0;
  double ar = 0.0;
  double h = 0.0;
  double n = 0.0;
  double anomalous_o = 0.0;
  double mass_density = 0.0;                   // gtd7 total, without anomalous O [kg/m^3]
  double mass_density_with_anomalous_o = 0.0;  // gtd7d total, for drag [kg/m^3]
  double exospheric_temperature = 0.0;         // T_inf [K]
  double temperature = 0.0;                    // at the height [K]
};

/// Lowest and highest geodetic height density() answers [m].
inline constexpr double kNrlmsise00MinHeight = 0.0;
inline constexpr double kNrlmsise00MaxHeight = 1000e3;

class Nrlmsise00Atmosphere final : public AtmosphereModel {
 public:
  /// The model of `coefficients` (checked with nrlmsise00_coefficients_problem; the error names
  /// the table entry).
  static core::Result<Nrlmsise00Atmosphere> create(const Nrlmsise00Coefficients& coefficients);

  Nrlmsise00Atmosphere(Nrlmsise00Atmosphere&&) noexcept;
  Nrlmsise00Atmosphere& operator=(Nrlmsise00Atmosphere&&) noexcept;
  ~Nrlmsise00Atmosphere() override;

  /// The problem of an input, or nullopt: every value finite and within the ranges of
  /// Nrlmsise00Input; f107, f107a > 0; ap and the ap_history values >= 0. The error names the
  /// field ("altitude_km", "activity.ap_history[3]", ...).
  static std::optional<core::Error> input_problem(const Nrlmsise00Input& input);

  /// Everything the model gives at `input`, after input_problem.
  [[nodiscard]] core::Result<Nrlmsise00Output> evaluate(const Nrlmsise00Input& input) const;

  /// The same, computed from scratch without the day/activity cache and without the identities
  /// of the cached path (phase and multiple-angle trigonometry, exp-log densities): the straightforward evaluation of the published equations,
  /// against which the fast path is tested (the two agree to ~1e-13 relative). Input as
  /// evaluate(); not checked (precondition: input_problem is nullopt).
  [[nodiscard]] Nrlmsise00Output evaluate_uncached(const Nrlmsise00Input& input) const;

  /// gtd7d's total mass density [kg/m^3] at the query: geodetic position of r_itrf on WGS-84, UTC
  /// day of year and seconds of `t`, lst = UT/3600 + longitude/15, the query's activity. 0 outside
  /// kNrlmsise00MinHeight..kNrlmsise00MaxHeight or for a non-finite position. No allocation.
  [[nodiscard]] double density(const AtmosphereQuery& query) const override;

  /// The model inputs density() uses at `query` (for reports and tests).
  [[nodiscard]] static Nrlmsise00Input input_at(const AtmosphereQuery& query);

  struct Model;  // opaque: the tables, the phase constants and the cache (nrlmsise00.cpp)

 private:
  explicit Nrlmsise00Atmosphere(std::unique_ptr<Model> model);
  std::unique_ptr<Model> model_;
};

}  // namespace visors::dynamics
