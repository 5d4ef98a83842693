#pragma once
// The GPS satellites of the truth world (ground side of the simulator): their true orbits and
// clocks, and the broadcast ephemerides a receiver decodes, which differ from the truth by the
// broadcast errors.
//
// Truth: each satellite's orbit and clock is its record of the constellation (gnss/constellation:
// a real 2024 record moved to the mission epoch), evaluated with the IS-GPS-200 algorithm.
// Broadcast: the same record with perturbed elements and clock polynomial, drawn once per run:
//   radial:       delta a ~ N(0, radial_m), with delta_n corrected so the mean motion, hence the
//                 along-track position, does not drift; delta (e cos w, e sin w) ~ N(0, radial_m / a)
//                 each (once-per-revolution radial +/- and along-track +/- 2x);
//   along-track:  delta M0 ~ N(0, along_m / a);
//   cross-track:  delta i0 ~ N(0, cross_m / a), delta Omega0 ~ N(0, cross_m / a) / sin i;
//   clock:        delta a_f0 ~ N(0, clock_m / c), delta a_f1 ~ N(0, clock_drift_sps).
// The errors are periodic (once per revolution) and bounded, like the broadcast errors of real
// ephemerides; defaults 0.4 / 1.0 / 0.6 m and 0.5 m give a ~1.3 m 3D orbit error, the level
// measured for the 2010 broadcast against IGS (tests/gnss). A broadcast error is common to both
// spacecraft, so it cancels in single differences except for ~|dr| x baseline / range = 1e-6 m
// at 40 m.
// Refresh (IS-GPS-200: a new data set every 2 h, 4-h fit interval): every refresh_s a new set
// per satellite, t_oe = t0 + k refresh_s (the receivers use the one nearest in t_oe, so each from
// t_oe - refresh_s / 2), the truth record re-expressed exactly at that t_oe (mean anomaly and node
// by their rates, inclination by IDOT, the clock polynomial re-centred) and perturbed by errors
// that follow a first-order autoregression from set to set: z_k = rho z_(k-1) + sqrt(1 - rho^2) w
// per unit draw, so a satellite's broadcast position jumps by ~sqrt(2 (1 - rho)) x its error at
// each switch (0.3 x at rho = 0.95: real consecutive sets agree at the decimetre level).
// Each satellite also has a constant fractional carrier-phase offset (phi^j_0, cycles), which
// cancels in double differences only.

#include <span>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/constellation.hpp"
#include "visors/sim/random_stream.hpp"

namespace visors::sim {

struct BroadcastErrorSettings {
  double radial_m = 0.4;            // 1-sigma [m]
  double along_m = 1.0;             // 1-sigma [m]
  double cross_m = 0.6;             // 1-sigma [m]
  double clock_m = 0.5;             // 1-sigma of the clock offset error, c * delta a_f0 [m]
  double clock_drift_sps = 1e-14;   // 1-sigma of delta a_f1 [s/s] (0.26 m per day)
  double refresh_s = 7200.0;        // a new data set every refresh_s (file comment); 0: one set
  double refresh_correlation = 0.95;  // rho of the errors from one set to the next, in [0, 1]

  /// Ok, or the field (finite, >= 0) by name.
  [[nodiscard]] core::Result<bool> validate() const;
};

class GpsSatelliteTruth {
 public:
  /// Draws the broadcast errors (file comment) from `rng`, six orbit and two clock numbers per
  /// satellite in PRN order, plus the phase offset; then, for the refreshed sets that cover
  /// `span_s` seconds after the constellation's t_oe, eight more per satellite and set.
  static core::Result<GpsSatelliteTruth> create(const gnss::GpsConstellation& constellation,
                                                const BroadcastErrorSettings& errors, RandomStream rng,
                                                double span_s = 0.0);

  /// The satellites (PRN order): true records, and the first broadcast set at the same index.
  [[nodiscard]] std::span<const gnss::BroadcastEphemeris> truth() const { return truth_; }
  [[nodiscard]] std::span<const gnss::BroadcastEphemeris> broadcast() const {
    return std::span(broadcast_).first(truth_.size());
  }
  /// Every broadcast set: the first, then each refresh (set by set, PRN order within a set).
  [[nodiscard]] std::span<const gnss::BroadcastEphemeris> broadcast_records() const { return broadcast_; }
  /// The satellite's constant carrier-phase offset [cycles, in [0, 1)].
  [[nodiscard]] double phase_offset_cycles(std::size_t index) const { return phase_offset_cycles_[index]; }

  /// True state at GPS time t; the clock is the L1 C/A clock (T_GD applied).
  [[nodiscard]] gnss::GpsSatelliteState true_state(std::size_t index, core::GpsTime t) const;

  /// The true position at t for a visibility screen (a receiver's elevation and occultation test):
  /// the last one evaluated for this satellite moved along its velocity when it is within
  /// kScreenReuseS of t (the two receivers of a step ask ~1 us apart: 4 mm of motion, and the
  /// linear move is off by a dt^2 / 2 ~ 3e-13 m), else a new evaluation. Not thread-safe (one
  /// simulation per object); allocation-free.
  [[nodiscard]] Eigen::Vector3d screening_position_ecef(std::size_t index, core::GpsTime t) const;
  static constexpr double kScreenReuseS = 1e-3;

 private:
  struct Screened {
    bool valid = false;
    core::GpsTime t;
    Eigen::Vector3d r_ecef_m = Eigen::Vector3d::Zero(), v_ecef_mps = Eigen::Vector3d::Zero();
  };
  std::vector<gnss::BroadcastEphemeris> truth_, broadcast_;
  std::vector<double> phase_offset_cycles_;
  mutable std::vector<Screened> screened_;  // sized at create()
};

}  // namespace visors::sim
