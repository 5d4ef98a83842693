#pragma once
// The host's 1 Hz time at tone as the truth sees it (ground side of the simulator). The flight
// software's time is not the true GPS time: the bus flight computer labels each tone with the
// whole GPS second its receiver's solution gives, and the tone happens when the receiver's
// pulse-per-second (PPS) says, so the instant labelled t is really t + offset:
//   - while the receiver has a solution (an epoch recorded with >= 4 satellites tracked), the
//     offset is the PPS error, N(0, pps_sigma_s) afresh each second;
//   - without one (outage, data gap, too few satellites), the computer's own oscillator keeps the
//     tone: the offset grows by the oscillator's fractional frequency error y (drawn once per
//     run, N(0, oscillator_sigma)) times the elapsed time, from the last PPS-disciplined value.
// Defaults: NovAtel OEM7 family data sheet (the paper's OEM719), time accuracy 20 ns RMS; a
// CubeSat computer's crystal of 10 ppm (an assumption: +-10-50 ppm is the range of uncompensated
// crystals; a TCXO would be 1 ppm).
//
// What the offset does in the closed loop (sim/campaign_simulation.cpp): every action of the flight
// software at its time t happens at t + offset, so an impulse commanded at t is executed offset
// later, which the truth applies as a position change -offset * dv (first order in offset; 20 ns or,
// after a 5-min outage, ~3 ms at 10 ppm: 6 um for a 2 mm/s impulse). The attitude reported at the
// tone is the one at t (the body turns ~1e-6 rad in 3 ms at the slew rate, far below the star
// tracker's error), and the receiver's measurements carry their own time tags and clock.

#include "visors/core/result.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct HostClockSettings {
  double pps_sigma_s = 20e-9;      // 1-sigma PPS error of the receiver's solution [s]
  double oscillator_sigma = 10e-6;  // 1-sigma fractional frequency error of the computer's oscillator [-]

  /// Ok, or the offending field by name (finite, >= 0; PPS <= 1 ms, oscillator <= 1e-3).
  [[nodiscard]] core::Result<bool> validate() const;
};

class HostClock {
 public:
  /// Draws the oscillator's frequency error from `rng` (the clock's own stream); errors name the field.
  static core::Result<HostClock> create(const HostClockSettings& settings, RandomStream rng);

  /// The tone of the second at t_s [s]: disciplined by the receiver's PPS when it has a solution,
  /// else free-running since the last tone. One normal draw a disciplined tone.
  void tone(double t_s, bool receiver_solution);

  /// True instant of the current tone minus its label [s].
  [[nodiscard]] double offset_s() const { return offset_s_; }
  /// The largest |offset| so far [s].
  [[nodiscard]] double max_abs_offset_s() const { return max_abs_offset_s_; }
  /// The oscillator's fractional frequency error this run [-].
  [[nodiscard]] double frequency_error() const { return frequency_error_; }

 private:
  HostClock(const HostClockSettings& settings, RandomStream rng);

  HostClockSettings settings_;
  RandomStream rng_;
  double frequency_error_ = 0.0;
  double offset_s_ = 0.0;
  double max_abs_offset_s_ = 0.0;
  double last_t_s_ = 0.0;
  bool started_ = false;
};

}  // namespace visors::sim
