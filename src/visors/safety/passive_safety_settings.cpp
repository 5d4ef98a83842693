#include "visors/safety/passive_safety_settings.hpp"

#include <cmath>

namespace visors::safety {

core::Status validate(const PassiveSafetySettings& s) {
  if (!(s.epsilon_m >= 0.0) || !std::isfinite(s.epsilon_m)) return core::Status{core::Problem::kOutOfRange, "epsilon_m", "must be a finite number >= 0 m"};
  if (!(s.horizon_orbits > 0.0) || s.horizon_orbits > 100.0) {
    return core::Status{core::Problem::kOutOfRange, "horizon_orbits", "must be in (0, 100] orbits"};
  }
  if (!(s.q_sigma >= 0.0) || s.q_sigma > 10.0) return core::Status{core::Problem::kOutOfRange, "q_sigma", "must be in [0, 10]"};
  if (!(s.check_period_s > 0.0) || !std::isfinite(s.check_period_s)) {
    return core::Status{core::Problem::kOutOfRange, "check_period_s", "must be a finite number > 0 s"};
  }
  if (s.samples_per_orbit < 8 || s.samples_per_orbit > 100000) {
    return core::Status{core::Problem::kOutOfRange, "samples_per_orbit", "must be in [8, 100000]"};
  }
  return {};
}

}  // namespace visors::safety
