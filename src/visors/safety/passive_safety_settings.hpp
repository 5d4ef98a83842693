#pragma once
// Configuration of the passive-safety check and the escape decision (Guffanti et al., AAS 23-149,
// 2023, Tables 3 and 5: checked every 10 s at 3 sigma, epsilon 5 m, RN plane; its Table 5 gives a
// horizon of 1.5 h, this default is 1.5 chief orbits, the longer and more conservative reading;
// docs/algorithms/safety.md#mission-settings). Every value is a parameter with this documented
// default.

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
  // 120 (3 deg): the separation's minima are about half an orbit apart, so every lobe has grid
  // points and the refinement finds its minimum (docs/algorithms/safety.md#horizon-evaluation).
  int samples_per_orbit = 120;
};

/// Each value checked; the error names the field ("epsilon_m", "horizon_orbits", ...).
core::Status validate(const PassiveSafetySettings& settings);

}  // namespace visors::safety
