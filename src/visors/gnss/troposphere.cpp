#include "visors/gnss/troposphere.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace visors::gnss {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;
constexpr double kMinHeightM = -500.0;
constexpr double kMaxHeightM = 10000.0;

// U.S. Standard Atmosphere 1976, part 1: sea-level values and the lowest layer's constants.
constexpr double kSeaLevelPressureHpa = 1013.25;
constexpr double kSeaLevelTemperatureK = 288.15;
constexpr double kLapseRateKPerM = 6.5e-3;
constexpr double kGravityMPerS2 = 9.80665;       // g0'
constexpr double kMolarMassKgPerMol = 28.9644e-3;  // M0
constexpr double kGasConstant = 8.31432;          // R* [J / (mol K)]
constexpr double kGeopotentialRadiusM = 6356766.0;  // r0 of eq. 18
constexpr double kPressureExponent = kGravityMPerS2 * kMolarMassKgPerMol / (kGasConstant * kLapseRateKPerM);
constexpr double kZeroCelsiusK = 273.15;

// Saastamoinen (1972) with the Davis et al. (1985) constant [m/hPa].
constexpr double kSaastamoinenMPerHpa = 0.0022768;

core::Result<double> checked_height(double height_m) {
  if (!(height_m >= kMinHeightM && height_m <= kMaxHeightM)) {
    return core::Error{"height_m", "must be in [-500, 10000] m"};
  }
  return height_m;
}

core::Result<double> checked_latitude(double latitude_rad) {
  if (!(std::abs(latitude_rad) <= 0.5 * kPi)) return core::Error{"latitude", "must be in [-pi/2, pi/2] rad"};
  return latitude_rad;
}

core::Result<double> checked_elevation(double elevation_rad) {
  if (!(elevation_rad > 0.0 && elevation_rad <= 0.5 * kPi)) {
    return core::Error{"elevation", "must be in (0, pi/2] rad"};
  }
  return elevation_rad;
}

// Tetens (1930) / Murray (1967): saturation vapour pressure over water [hPa], t in degC.
double saturation_vapour_pressure_hpa(double temperature_c) {
  return 6.1078 * std::exp(17.27 * temperature_c / (temperature_c + 237.3));
}

// Marini (1972) continued fraction normalised to 1 at the zenith (Niell 1996).
double marini(double sin_e, double a, double b, double c) {
  const double top = 1.0 + a / (1.0 + b / (1.0 + c));
  return top / (sin_e + a / (sin_e + b / (sin_e + c)));
}

// Niell (1996) Table 3, rows at |latitude| = 15, 30, 45, 60, 75 deg.
using Row = std::array<double, 5>;
constexpr std::array<Row, 3> kHydrostaticAverage{{
    {1.2769934e-3, 1.2683230e-3, 1.2465397e-3, 1.2196049e-3, 1.2045996e-3},  // a
    {2.9153695e-3, 2.9152299e-3, 2.9288445e-3, 2.9022565e-3, 2.9024912e-3},  // b
    {62.610505e-3, 62.837393e-3, 63.721774e-3, 63.824265e-3, 64.258455e-3},  // c
}};
constexpr std::array<Row, 3> kHydrostaticAmplitude{{
    {0.0, 1.2709626e-5, 2.6523662e-5, 3.4000452e-5, 4.1202191e-5},
    {0.0, 2.1414979e-5, 3.0160779e-5, 7.2562722e-5, 11.723375e-5},
    {0.0, 9.0128400e-5, 4.3497037e-5, 84.795348e-5, 170.37206e-5},
}};
constexpr std::array<Row, 3> kWet{{
    {5.8021897e-4, 5.6794847e-4, 5.8118019e-4, 5.9727542e-4, 6.1641693e-4},
    {1.4275268e-3, 1.5138625e-3, 1.4572752e-3, 1.5007428e-3, 1.7599082e-3},
    {4.3472961e-2, 4.6729510e-2, 4.3908931e-2, 4.4626982e-2, 5.4736038e-2},
}};
constexpr std::array<double, 3> kHeightCorrection{2.53e-5, 5.49e-3, 1.14e-3};  // a, b, c per km

// Linear in |latitude| [deg] between the rows, constant beyond 15 and 75 deg.
double interpolate(const Row& row, double abs_latitude_deg) {
  if (abs_latitude_deg <= 15.0) return row[0];
  if (abs_latitude_deg >= 75.0) return row[4];
  const double x = abs_latitude_deg / 15.0 - 1.0;  // in (0, 4)
  const auto i = static_cast<std::size_t>(x);
  const double f = x - static_cast<double>(i);
  return row[i] * (1.0 - f) + row[i + 1] * f;
}

// Day of the year [d] counted from January 0.0 GPST (1.0 at January 1, 00:00), as in Niell's code.
double day_of_year(core::GpsTime t) {
  constexpr std::array<int, 12> kDaysBefore{0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const core::CalendarTime c = t.calendar(core::TimeScale::kGps);
  const bool leap = (c.year % 4 == 0 && c.year % 100 != 0) || c.year % 400 == 0;
  const int day = kDaysBefore[static_cast<std::size_t>(c.month - 1)] + c.day + (leap && c.month > 2 ? 1 : 0);
  const double seconds = c.hour * 3600.0 + c.minute * 60.0 + c.second + static_cast<double>(c.nanosecond) * 1e-9;
  return day + seconds / 86400.0;
}

double niell_hydrostatic(double latitude_rad, double height_m, double sin_e, core::GpsTime t) {
  const double abs_lat_deg = std::abs(latitude_rad) / kDeg;
  // Seasonal phase: minimum of the coefficients near January 28 north, half a year later south.
  const double days = day_of_year(t) - 28.0 + (latitude_rad < 0.0 ? 365.25 / 2.0 : 0.0);
  const double cos_season = std::cos(2.0 * kPi * days / 365.25);
  std::array<double, 3> abc{};
  for (std::size_t k = 0; k < 3; ++k) {
    abc[k] = interpolate(kHydrostaticAverage[k], abs_lat_deg) - interpolate(kHydrostaticAmplitude[k], abs_lat_deg) * cos_season;
  }
  const double sea_level = marini(sin_e, abc[0], abc[1], abc[2]);
  const double per_km = 1.0 / sin_e - marini(sin_e, kHeightCorrection[0], kHeightCorrection[1], kHeightCorrection[2]);
  return sea_level + per_km * height_m * 1e-3;
}

double niell_wet(double latitude_rad, double sin_e) {
  const double abs_lat_deg = std::abs(latitude_rad) / kDeg;
  return marini(sin_e, interpolate(kWet[0], abs_lat_deg), interpolate(kWet[1], abs_lat_deg),
                interpolate(kWet[2], abs_lat_deg));
}

}  // namespace

core::Result<StandardAtmosphere> standard_atmosphere(double height_m, double relative_humidity) {
  if (const auto h = checked_height(height_m); !h.ok()) return h.error();
  if (!(relative_humidity >= 0.0 && relative_humidity <= 1.0)) {
    return core::Error{"relative_humidity", "must be in [0, 1]"};
  }
  const double geopotential_m = kGeopotentialRadiusM * height_m / (kGeopotentialRadiusM + height_m);  // eq. 18
  const double temperature_k = kSeaLevelTemperatureK - kLapseRateKPerM * geopotential_m;              // eq. 23
  StandardAtmosphere a;
  a.temperature_k = temperature_k;
  a.pressure_hpa = kSeaLevelPressureHpa * std::pow(temperature_k / kSeaLevelTemperatureK, kPressureExponent);  // eq. 33a
  a.water_vapour_pressure_hpa = relative_humidity * saturation_vapour_pressure_hpa(temperature_k - kZeroCelsiusK);
  return a;
}

core::Result<ZenithDelays> saastamoinen_zenith_delays_m(double latitude_rad, double height_m,
                                                        const TroposphereSettings& settings) {
  if (const auto lat = checked_latitude(latitude_rad); !lat.ok()) return lat.error();
  const auto atmosphere = standard_atmosphere(height_m, settings.relative_humidity);
  if (!atmosphere.ok()) return atmosphere.error();
  // Gravity at the centroid of the column relative to 45 deg and sea level (Saastamoinen 1972).
  const double gravity_factor = 1.0 - 0.00266 * std::cos(2.0 * latitude_rad) - 0.00028 * height_m * 1e-3;
  ZenithDelays z;
  z.hydrostatic_m = kSaastamoinenMPerHpa * atmosphere->pressure_hpa / gravity_factor;
  z.wet_m = kSaastamoinenMPerHpa * (1255.0 / atmosphere->temperature_k + 0.05) * atmosphere->water_vapour_pressure_hpa;
  return z;
}

core::Result<MappingFactors> niell_mapping(double latitude_rad, double height_m, double elevation_rad,
                                           core::GpsTime t) {
  if (const auto lat = checked_latitude(latitude_rad); !lat.ok()) return lat.error();
  if (const auto h = checked_height(height_m); !h.ok()) return h.error();
  if (const auto e = checked_elevation(elevation_rad); !e.ok()) return e.error();
  const double sin_e = std::sin(elevation_rad);
  return MappingFactors{niell_hydrostatic(latitude_rad, height_m, sin_e, t), niell_wet(latitude_rad, sin_e)};
}

core::Result<double> saastamoinen_delay_m(double latitude_rad, double height_m, double elevation_rad,
                                          const TroposphereSettings& settings, core::GpsTime t) {
  const auto zenith = saastamoinen_zenith_delays_m(latitude_rad, height_m, settings);
  if (!zenith.ok()) return zenith.error();
  if (const auto e = checked_elevation(elevation_rad); !e.ok()) return e.error();
  MappingFactors m{1.0 / std::sin(elevation_rad), 1.0 / std::sin(elevation_rad)};
  if (settings.mapping == TroposphereMapping::kNiell1996) {
    const auto niell = niell_mapping(latitude_rad, height_m, elevation_rad, t);
    if (!niell.ok()) return niell.error();
    m = *niell;
  }
  return zenith->hydrostatic_m * m.hydrostatic + zenith->wet_m * m.wet;
}

}  // namespace visors::gnss
