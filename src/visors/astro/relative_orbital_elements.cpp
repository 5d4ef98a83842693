#include "visors/astro/relative_orbital_elements.hpp"

#include <cmath>

#include "visors/core/angles.hpp"
#include "visors/core/constants.hpp"

namespace visors::astro {
namespace {

core::Status validate_named(const KeplerianElements& el, const char* who) {
  return validate_keplerian(el).status().within(who);
}

// The QNS set is singular at i_c = 0 or pi (diy = dRAAN sin i_c carries no information there).
constexpr double kMinSinInclination = 1e-10;

}  // namespace

core::Outcome<RelativeOrbitalElements> roe_from_keplerian(const KeplerianElements& chief,
                                                         const KeplerianElements& deputy) {
  if (auto c = validate_named(chief, "chief"); !c) return c;
  if (auto d = validate_named(deputy, "deputy"); !d) return d;
  const double si = std::sin(chief.i);
  if (std::abs(si) < kMinSinInclination) {
    return core::Status{core::Problem::kSingular, "chief.i", "must not be equatorial (ROE are singular at i = 0, pi)"};
  }
  const double d_raan = core::wrap_pi(deputy.raan - chief.raan);
  const double d_u = core::wrap_pi((deputy.argp + deputy.M) - (chief.argp + chief.M));
  RelativeOrbitalElements roe;
  roe[roe::kDa] = (deputy.a - chief.a) / chief.a;
  roe[roe::kDlambda] = core::wrap_pi(d_u + d_raan * std::cos(chief.i));
  roe[roe::kDex] = deputy.e * std::cos(deputy.argp) - chief.e * std::cos(chief.argp);
  roe[roe::kDey] = deputy.e * std::sin(deputy.argp) - chief.e * std::sin(chief.argp);
  roe[roe::kDix] = deputy.i - chief.i;
  roe[roe::kDiy] = d_raan * si;
  return roe;
}

core::Outcome<KeplerianElements> deputy_from_roe(const KeplerianElements& chief,
                                                const RelativeOrbitalElements& roe) {
  if (auto c = validate_named(chief, "chief"); !c) return c;
  if (!roe.allFinite()) return core::Status{core::Problem::kNotFinite, "roe", "must be finite"};
  const double si = std::sin(chief.i);
  if (std::abs(si) < kMinSinInclination) {
    return core::Status{core::Problem::kSingular, "chief.i", "must not be equatorial (ROE are singular at i = 0, pi)"};
  }
  if (roe[roe::kDa] <= -1.0) return core::Status{core::Problem::kOutOfRange, "roe.da", "must be > -1 (deputy a > 0)"};
  KeplerianElements dep;
  dep.a = chief.a * (1.0 + roe[roe::kDa]);
  dep.i = chief.i + roe[roe::kDix];
  const double d_raan = roe[roe::kDiy] / si;
  dep.raan = chief.raan + d_raan;
  const double ex = chief.e * std::cos(chief.argp) + roe[roe::kDex];
  const double ey = chief.e * std::sin(chief.argp) + roe[roe::kDey];
  dep.e = std::hypot(ex, ey);
  if (dep.e >= 1.0) return core::Status{core::Problem::kOutOfRange, "roe.dex", "deputy eccentricity must be < 1"};
  dep.argp = dep.e > 0.0 ? std::atan2(ey, ex) : 0.0;
  const double u = chief.argp + chief.M + roe[roe::kDlambda] - d_raan * std::cos(chief.i);
  dep.M = u - dep.argp;
  if (dep.i < 0.0 || dep.i > core::kPi) {
    return core::Status{core::Problem::kOutOfRange, "roe.dix", "deputy inclination must be in [0, pi]"};
  }
  return dep;
}

}  // namespace visors::astro
