#pragma once
// Constants of the GPS user algorithms, IS-GPS-200 (Rev. N) 20.3.3.4.3 and 20.3.4.3. The
// ephemeris and almanac parameters were fitted with exactly these values, so the user algorithm
// must use them (not the IERS values): a different mu gives a metre-level along-track error after
// hours (docs/algorithms/gnss-measurements.md#gps-constants).

namespace visors::gnss {

inline constexpr double kGpsMu = 3.986005e14;                // WGS-84 GM for GPS [m^3/s^2]
inline constexpr double kGpsEarthRate = 7.2921151467e-5;     // WGS-84 Earth rotation rate [rad/s]
inline constexpr double kGpsPi = 3.1415926535898;            // the document's pi (semicircles)
inline constexpr double kGpsRelativisticF = -4.442807633e-10;  // F = -2 sqrt(mu) / c^2 [s/m^(1/2)]
inline constexpr double kGpsSpeedOfLight = 299792458.0;      // [m/s]
inline constexpr double kL1FrequencyHz = 1575.42e6;          // L1 carrier [Hz]
inline constexpr double kL1WavelengthM = kGpsSpeedOfLight / kL1FrequencyHz;  // 0.190293672798 m
inline constexpr double kL2FrequencyHz = 1227.60e6;          // L2 carrier [Hz]
inline constexpr double kL2WavelengthM = kGpsSpeedOfLight / kL2FrequencyHz;  // 0.244210213425 m
inline constexpr int kMaxGpsPrn = 32;                        // PRN 1..32

}  // namespace visors::gnss
