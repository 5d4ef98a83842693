#pragma once
// What one GPS receiver delivers per epoch to the navigation filter: L1 C/A code and carrier
// phase per tracked satellite, with the receiver's loss-of-lock indicator (RINEX LLI bit 0: the
// phase may have slipped since the previous epoch). Fixed capacity: kGpsSlots channels.

#include <array>
#include <optional>

#include "core/gps_time.hpp"
#include "core/status.hpp"
#include "nav/navigation_state.hpp"

namespace visors::nav {

struct GpsObservation {
  int prn = 0;                // 1..32
  double code_m = 0.0;        // C/A pseudorange [m]
  double phase_cycles = 0.0;  // L1 carrier phase [cycles] (RINEX sign: grows with the range)
  bool loss_of_lock = false;  // a slip may have occurred since the previous epoch
};

struct GpsReceiverEpoch {
  core::GpsTime t;  // the receiver's time tag
  int count = 0;    // observations used, 0..kGpsSlots
  std::array<GpsObservation, kGpsSlots> observations{};

  /// The observation of `prn`, or nullptr.
  [[nodiscard]] const GpsObservation* find(int prn) const;
};

/// Input validation at the filter's boundary: count in range, PRNs in 1..32 and distinct, values
/// finite, code in [1.9e7, 3.0e7] m (a LEO receiver's GPS ranges, plus a clock offset of up to
/// 1 ms). The error names the field ("observations[3].code_m").
std::optional<core::Error> check(const GpsReceiverEpoch& epoch);

}  // namespace visors::nav
