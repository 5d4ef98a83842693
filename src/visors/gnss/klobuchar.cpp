#include "visors/gnss/klobuchar.hpp"

#include <algorithm>
#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::gnss {

namespace {
constexpr double kPi = 3.14159265358979323846;  // the document's semicircle-to-radian factor
constexpr double kDay = 86400.0;
// The smaller root of the cosine polynomial 1 - x^2/2 + x^4/24: x^2 = 6 - 2 sqrt(3).
const double kPolynomialRoot = std::sqrt(6.0 - 2.0 * std::sqrt(3.0));  // 1.5924...

// IS-GPS-200 Figure 20-4 with the day-time term used for |x| < x_night (the document's 1.57, or
// the root of its cosine polynomial for the topside model: klobuchar.hpp).
core::Result<double> delay_s(const KlobucharCoefficients& c, const KlobucharGeometry& g, core::GpsTime t, double x_night) {
  for (int n = 0; n < 4; ++n) {
    if (!std::isfinite(c.alpha[static_cast<std::size_t>(n)])) return core::Error{"alpha", "must be finite"};
    if (!std::isfinite(c.beta[static_cast<std::size_t>(n)])) return core::Error{"beta", "must be finite"};
  }
  if (!(std::abs(g.latitude) <= 0.5 * kPi)) return core::Error{"lat", "must be in [-pi/2, pi/2] rad"};
  if (!std::isfinite(g.longitude)) return core::Error{"lon", "must be finite"};
  if (!std::isfinite(g.azimuth)) return core::Error{"az", "must be finite"};
  if (!(g.elevation >= 0.0 && g.elevation <= 0.5 * kPi)) return core::Error{"el", "must be in [0, pi/2] rad"};

  // IS-GPS-200 Figure 20-4, in semicircles.
  const double phi_u = g.latitude / kPi;
  const double lambda_u = g.longitude / kPi;
  const double e = g.elevation / kPi;
  const double psi = 0.0137 / (e + 0.11) - 0.022;                        // Earth angle to the pierce point
  const double phi_i = std::clamp(phi_u + psi * std::cos(g.azimuth), -0.416, 0.416);
  const double lambda_i = lambda_u + psi * std::sin(g.azimuth) / std::cos(phi_i * kPi);
  const double phi_m = phi_i + 0.064 * std::cos((lambda_i - 1.617) * kPi);  // geomagnetic latitude
  // Local time at the pierce point [s], in [0, 86400): GPS time of day plus the longitude.
  double local = 4.32e4 * lambda_i + std::fmod(t.seconds_of_week(), kDay);
  local -= std::floor(local / kDay) * kDay;
  double amplitude = 0.0, period = 0.0, power = 1.0;
  for (int n = 0; n < 4; ++n) {
    amplitude += c.alpha[static_cast<std::size_t>(n)] * power;
    period += c.beta[static_cast<std::size_t>(n)] * power;
    power *= phi_m;
  }
  amplitude = std::max(amplitude, 0.0);
  period = std::max(period, 72000.0);
  const double x = 2.0 * kPi * (local - 50400.0) / period;  // phase [rad]
  const double obliquity = 1.0 + 16.0 * std::pow(0.53 - e, 3);
  if (std::abs(x) >= x_night) return obliquity * 5e-9;  // night-time constant
  return obliquity * (5e-9 + amplitude * (1.0 - x * x / 2.0 + x * x * x * x / 24.0));
}

}  // namespace

core::Result<double> klobuchar_delay_s(const KlobucharCoefficients& c, const KlobucharGeometry& g, core::GpsTime t) {
  return delay_s(c, g, t, 1.57);
}

core::Result<double> klobuchar_delay_m(const KlobucharCoefficients& c, const KlobucharGeometry& g, core::GpsTime t) {
  const auto delay = klobuchar_delay_s(c, g, t);
  if (!delay.ok()) return delay.error();
  return *delay * core::kSpeedOfLight;
}

core::Result<double> klobuchar_topside_delay_m(const KlobucharCoefficients& c, const KlobucharGeometry& g,
                                               double altitude_m, core::GpsTime t, const TopsideIonosphere& topside) {
  constexpr double kMeanEarthRadius = 6371e3;  // [m]
  if (!(topside.topside_fraction >= 0.0 && topside.topside_fraction <= 1.0)) {
    return core::Error{"topside_fraction", "must be in [0, 1]"};
  }
  if (!std::isfinite(altitude_m)) return core::Error{"altitude_m", "must be finite"};
  if (!(topside.shell_height_m > altitude_m)) return core::Error{"shell_height_m", "must be above the receiver's altitude"};
  if (!(std::abs(g.elevation) <= 0.5 * kPi)) return core::Error{"el", "must be in [-pi/2, pi/2] rad"};
  KlobucharGeometry zenith = g;
  zenith.elevation = 0.5 * kPi;
  const auto zenith_delay_s = delay_s(c, zenith, t, kPolynomialRoot);  // continuous (header)
  if (!zenith_delay_s.ok()) return zenith_delay_s.error();
  const double obliquity_at_zenith = 1.0 + 16.0 * std::pow(0.53 - 0.5, 3);
  const double zenith_delay_m = *zenith_delay_s * core::kSpeedOfLight;
  const double vertical = topside.topside_fraction * zenith_delay_m / obliquity_at_zenith;
  const double ratio = (kMeanEarthRadius + altitude_m) * std::cos(std::max(g.elevation, 0.0)) /
                       (kMeanEarthRadius + topside.shell_height_m);
  return vertical / std::sqrt(1.0 - ratio * ratio);
}

}  // namespace visors::gnss
