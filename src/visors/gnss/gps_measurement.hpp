#pragma once
// One epoch of raw L1 C/A measurements from a GPS receiver: what the receiver gives the flight
// computer at 1 Hz (the flight component's GPS message) and what a RINEX observation epoch holds.
// Fixed capacity (12 channels), so a message is a plain value: no allocation on the way.
//
// Observables (RINEX 3.05 section 5.2 conventions): pseudorange [m] = c (receiver time tag -
// transmission time by the satellite clock); carrier phase [cycles] with the sign that makes it
// grow with the range, so phase * lambda - pseudorange is constant plus twice the ionosphere over
// a continuous track.

#include <array>
#include <cstdint>

#include "visors/core/status.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"

namespace visors::gnss {

inline constexpr int kMaxGpsChannels = 12;

struct GpsChannelMeasurement {
  int prn = 0;
  double pseudorange_m = 0.0;         // C1C [m]
  double carrier_phase_cycles = 0.0;  // L1C [cycles]
  double doppler_hz = 0.0;            // D1C [Hz], positive when approaching
  double cn0_dbhz = 0.0;              // S1C [dB-Hz]
  /// The phase may have slipped since the previous epoch (RINEX LLI bit 0): a new ambiguity.
  bool loss_of_lock = false;
  double lock_time_s = 0.0;  // continuous tracking so far [s]
  /// Unresolved half-cycle ambiguity in the phase (RINEX LLI bit 1). Last, so the aggregate
  /// initialisations of the fields above keep their meaning.
  bool half_cycle_ambiguity = false;
};

struct GpsMeasurementEpoch {
  core::GpsTime t;  // the receiver's time tag (receiver clock, not true GPS time)
  int channel_count = 0;
  std::array<GpsChannelMeasurement, kMaxGpsChannels> channels{};
};

/// Field-named checks: channel_count in 0..12; per channel PRN in 1..32 and not repeated, values
/// finite, pseudorange in [1e7, 5e7] m (any receiver from the ground to above LEO, with a clock
/// offset below 30 ms), C/N0 in [0, 70] dB-Hz, lock time >= 0.
core::Status validate(const GpsMeasurementEpoch& epoch);

}  // namespace visors::gnss
