#include "nav/gps_observations.hpp"

#include <cmath>
#include <string>

namespace visors::nav {

const GpsObservation* GpsReceiverEpoch::find(int prn) const {
  for (int i = 0; i < count; ++i) {
    if (observations[static_cast<std::size_t>(i)].prn == prn) return &observations[static_cast<std::size_t>(i)];
  }
  return nullptr;
}

std::optional<core::Error> check(const GpsReceiverEpoch& epoch) {
  if (epoch.count < 0 || epoch.count > kGpsSlots) {
    return core::Error{"count", "must be in [0, " + std::to_string(kGpsSlots) + "]"};
  }
  constexpr double kMinRange = 1.9e7, kMaxRange = 3.0e7;  // [m]
  for (int i = 0; i < epoch.count; ++i) {
    const GpsObservation& o = epoch.observations[static_cast<std::size_t>(i)];
    const std::string field = "observations[" + std::to_string(i) + "].";
    if (o.prn < 1 || o.prn > 32) return core::Error{field + "prn", "must be in [1, 32]"};
    for (int j = 0; j < i; ++j) {
      if (epoch.observations[static_cast<std::size_t>(j)].prn == o.prn) return core::Error{field + "prn", "repeats an earlier one"};
    }
    if (!(o.code_m >= kMinRange && o.code_m <= kMaxRange)) return core::Error{field + "code_m", "must be in [1.9e7, 3.0e7] m"};
    if (!std::isfinite(o.phase_cycles)) return core::Error{field + "phase_cycles", "must be finite"};
  }
  return std::nullopt;
}

}  // namespace visors::nav
