#pragma once
// What one GPS receiver delivers per epoch to the navigation filter: L1 C/A code and carrier
// phase per tracked satellite, with the receiver's loss-of-lock indicator (RINEX LLI bit 0: the
// phase may have slipped since the previous epoch). Fixed capacity: kGpsSlots channels.

#include <array>
#include <optional>

#include "visors/core/status.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/gps_measurement.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

struct GpsObservation {
  int prn = 0;                // 1..32
  double code_m = 0.0;        // C/A pseudorange [m]
  double phase_cycles = 0.0;  // L1 carrier phase [cycles] (RINEX sign: grows with the range)
  bool loss_of_lock = false;  // a slip may have occurred since the previous epoch
  bool half_cycle = false;    // the phase may be off by half a cycle (RINEX 3 LLI bit 1), until resolved
};

struct GpsReceiverEpoch {
  core::GpsTime t;  // the receiver's time tag
  int count = 0;    // observations used, 0..kGpsSlots
  std::array<GpsObservation, kGpsSlots> observations{};

  /// The observation of `prn`, or nullptr.
  [[nodiscard]] const GpsObservation* find(int prn) const;
};

/// The filter's view of a receiver's epoch (gnss/gps_measurement.hpp, the flight component's GPS
/// message): code, phase and the two loss-of-lock bits per channel, in channel order.
GpsReceiverEpoch receiver_epoch(const gnss::GpsMeasurementEpoch& measurement);

/// Input validation of an epoch's structure at the filter's boundary: count in range, PRNs in
/// 1..32 and distinct. The error names the field ("observations[3].prn"); such an epoch is refused.
core::Status check(const GpsReceiverEpoch& epoch);

/// Whether one observation's values are usable: finite, code in [1.5e7, 3.5e7] m (a LEO
/// receiver's geometric ranges to GPS, 1.97e7-2.6e7 m, plus satellite and receiver clock offsets
/// of a few milliseconds: a broadcast a_f0 of 2.3 ms was seen in the simulation's navigation
/// file). An implausible observation is skipped and counted, the rest of its epoch used.
bool plausible(const GpsObservation& observation);

}  // namespace visors::nav
