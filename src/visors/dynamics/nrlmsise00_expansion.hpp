#pragma once
// The spherical-harmonic expansions G(L) of NRLMSISE-00 (internal to nrlmsise00.cpp): the full
// expansion of the thermosphere (Hedin 1987, JGR 92(A5) 4649, appendix eqs. A22-A24; the published
// routine globe7) and the shorter one of the lower thermosphere and middle atmosphere (Hedin 1991,
// JGR 96(A2) 1159; the published routine glob7s), with every switch on.
//
// Each expansion is a sum of terms: F10.7, time independent (zonal Legendre functions of the
// latitude), annual and semiannual (cosines of the day of year), diurnal, semidiurnal and
// terdiurnal tides (harmonics of the local time), geomagnetic activity, longitude and UT. Their
// inputs split three ways, which is what makes the cached evaluation cheap:
//   * Basis: the position and time of the call (Legendre functions, local-time harmonics, ...);
//   * DayTerms: per table, what depends only on the day of year and the solar/geomagnetic
//     activity (seasonal cosines, F10.7 factors, the geomagnetic function when it does not
//     depend on latitude);
//   * PhaseTerms: per table, the cosines of a phase-shifted local time, longitude or UT. The
//     direct evaluation takes cos(a - p) as written; the cached one uses
//     cos(a - p) = cos a cos p + sin a sin p with cos p, sin p of each table precomputed.

#include <array>
#include <optional>

#include "visors/dynamics/atmosphere.hpp"

namespace visors::dynamics::nrlmsise00_detail {

// The published model's own constants (used as published: changing them changes the 6th-7th digit).
inline constexpr double kDegree = 1.74533e-2;  // degree [rad]
inline constexpr double kDay = 1.72142e-2;     // day of the annual cycle [rad] (2 pi / 365)
inline constexpr double kHour = 0.2618;        // hour of local time [rad] (2 pi / 24)
inline constexpr double kSecond = 7.2722e-5;   // second of UT [rad] (2 pi / 86400)

using FullTable = std::array<double, 150>;
using LowerTable = std::array<double, 100>;

/// The per-call inputs shared by every expansion.
struct Basis {
  // Associated Legendre functions of sin(latitude), legendre[m][n] = P_n^m (unnormalised, no
  // Condon-Shortley phase), the degrees and orders the model uses (Hedin 1987 eq. A22).
  std::array<std::array<double, 8>, 4> legendre{};
  double cos_lt1 = 0.0, sin_lt1 = 0.0;  // cos, sin of kHour * lst
  double cos_lt2 = 0.0, sin_lt2 = 0.0;  // ... 2 kHour lst
  double cos_lt3 = 0.0, sin_lt3 = 0.0;  // ... 3 kHour lst
  double cos_lon = 0.0, sin_lon = 0.0;  // of kDegree * longitude
  double cos_ut = 0.0, sin_ut = 0.0;    // of kSecond * UT (cached path only)
  double cos_ut_lon = 0.0, sin_ut_lon = 0.0;  // of kSecond UT + 2 kDegree longitude (cached path)
  double lst_h = 0.0;
  double longitude_deg = 0.0;
  double latitude_deg = 0.0;
  double ut_seconds = 0.0;
  double dfa = 0.0;  // f107a - 150 [sfu]
};

/// The basis at a latitude, longitude, local time, UT and 81-day mean flux. `cached_path`: the
/// harmonics of 2 tau and 3 tau from those of tau by the double- and triple-angle identities
/// (cos 2t = c^2 - s^2, sin 2t = 2 s c, cos 3t = c (c^2 - 3 s^2), sin 3t = s (3 c^2 - s^2)), and
/// cos_ut .. sin_ut_lon filled (the phase identities need them); otherwise each harmonic is
/// taken directly, as published.
Basis make_basis(double latitude_deg, double longitude_deg, double lst_h, double ut_seconds, double f107a,
                 bool cached_path);

/// Per full table: what depends only on the day of year and the activity.
struct FullDayTerms {
  double cd14 = 0.0, cd18 = 0.0, cd32 = 0.0, cd39 = 0.0;  // seasonal cosines (Hedin 1987 eq. A22)
  double f1 = 0.0, f2 = 0.0;                              // F10.7 factors of the annual term and the tides
  double flux = 0.0;                                      // the F10.7 term
  // The geomagnetic function (magnetic_function) when it does not depend on latitude, else
  // nullopt (computed per call from history_scaled).
  std::optional<double> magnetic;
  // History mode: the scaled ap g(ap1) .. g(ap6) of eq. A24d (they do not depend on latitude).
  std::array<double, 6> history_scaled{};
};

/// Per lower table: what depends only on the day of year.
struct LowerDayTerms {
  double cd14 = 0.0, cd18 = 0.0, cd32 = 0.0, cd39 = 0.0;
  double lon_annual = 0.0;  // multiplies P_1^0 in the longitude term's seasonal factor
  double lon_constant = 0.0;  // the rest of that factor (1 + lon_annual P_1^0 + lon_constant)
};

/// Per full table: the phase-shifted cosines of one call.
struct FullPhaseTerms {
  double lt_magnetic = 0.0;  // cos(kHour (lst - p[124])) daily, p[131] history
  double ut = 0.0;           // cos(kSecond (UT - p[71]))
  double ut_lon = 0.0;       // cos(kSecond (UT - p[79]) + 2 kDegree lon)
  double lon_magnetic1 = 0.0;  // cos(kDegree (lon - p[63])) daily, p[97] history
  double lon_magnetic2 = 0.0;  // cos(kDegree (lon - p[118])) daily, p[136] history
  double ut_magnetic = 0.0;    // cos(kSecond (UT - p[75])) daily, p[58] history
};

/// cos and sin of each phase constant of a full table (the cached path's identities).
struct FullPhaseConstants {
  std::array<double, 6> cos_phase{};
  std::array<double, 6> sin_phase{};
};

/// Whether the query runs the ap-history mode (published switch 9 = -1).
inline bool history_mode(const SolarActivity& a) { return a.ap_history.has_value(); }

/// The geomagnetic function of table `p` for `activity` (Hedin 1987 appendix, eq. A24 and the
/// NRL code): daily mode, with a = Ap - 4,
///   apdf = a + (p[44] - 1) (a + (exp(-p[43] a) - 1) / p[43]),   p[43] -> 1e-5 if < 0;
/// history mode (eqs. A24a-d), with the decay factor
///   e = min(exp(-10800 |p[51]| / (1 + p[138] (45 - |latitude|))), 0.99999),
///   g(x) = x - 4 + (p[25] - 1) (x - 4 + (exp(-k (x - 4)) - 1) / k),   k = |max(p[24], 1e-4)|,
///   apt = (g(ap1) + g(ap2) e + g(ap3) e^2 + g(ap4) e^3 + (g(ap5) e^4 + g(ap6) e^12)(1 - e^8)/(1 - e))
///         / (1 + (1 - e^19) / (1 - e) sqrt(e)),
/// ap0..ap6 the ap_history elements; 0 when p[51] = 0 (the table has no history terms).
double magnetic_function(const FullTable& p, const SolarActivity& activity, double latitude_deg);
/// Whether that function depends on latitude (history mode with p[138] != 0).
bool magnetic_depends_on_latitude(const FullTable& p, const SolarActivity& activity);
/// The history-mode function from the day terms' history_scaled (the same value as
/// magnetic_function, with the powers of the decay factor by repeated multiplication).
double magnetic_function_cached(const FullTable& p, const FullDayTerms& day, double latitude_deg);

FullDayTerms full_day_terms(const FullTable& p, int day_of_year, const SolarActivity& activity);
LowerDayTerms lower_day_terms(const LowerTable& p, int day_of_year);

/// The phase terms computed directly, cos(a - p) as written.
FullPhaseTerms direct_phase_terms(const FullTable& p, const Basis& b, bool history);
/// The phase constants of a table for one mode, and the phase terms from them by the identity.
FullPhaseConstants phase_constants(const FullTable& p, bool history);
FullPhaseTerms cached_phase_terms(const FullPhaseConstants& k, const Basis& b);

/// G(L) of a full table (globe7 with every switch on), including its constant p[30].
double full_expansion(const FullTable& p, const Basis& b, const FullDayTerms& day, const FullPhaseTerms& phase,
                      double magnetic, bool history);
/// G(L) of a lower table (glob7s with every switch on). `magnetic` is the geomagnetic function
/// the published code carries over from the last full expansion evaluated before it: that of
/// T_lb's table pd[3] (lower-thermosphere nodes); the middle-atmosphere tables have no
/// geomagnetic coefficients.
double lower_expansion(const LowerTable& p, const Basis& b, const LowerDayTerms& day, double magnetic, bool history);

}  // namespace visors::dynamics::nrlmsise00_detail
