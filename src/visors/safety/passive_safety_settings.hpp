#pragma once
// Configuration of the passive-safety check and the escape decision (mission paper: checked every
// 10 s over a 1.5-orbit horizon at 3 sigma, epsilon 5 m, RN plane). Every value is a parameter
// with this documented default.

#include "visors/core/status.hpp"

namespace visors::safety {

enum class SafetyPlane { kRadialNormal, kThreeDimensional };

struct PassiveSafetySettings {
  double epsilon_m = 5.0;          // minimum separation that is still safe [m]
  double horizon_orbits = 1.5;     // T: look-ahead of the check [chief orbits]
  double q_sigma = 3.0;            // the separation is reduced by q standard deviations [-]
  SafetyPlane plane = SafetyPlane::kRadialNormal;
  double check_period_s = 10.0;    // how often the flight component runs the check [s]
  // Grid of the minimum search (each grid minimum refined by golden section) [per chief orbit].
  // 120 (3 deg): the separation's minima are half an orbit apart; over the default campaign the
  // margins equal those of a 360 grid to 1e-13 m (15,082 checks compared), at half the cost.
  int samples_per_orbit = 120;
};

/// Each value checked; the error names the field ("epsilon_m", "horizon_orbits", ...).
core::Result<PassiveSafetySettings> validate(const PassiveSafetySettings& settings);

}  // namespace visors::safety
