#pragma once
// A GPS constellation at an epoch for which no navigation file exists (the mission epoch
// 2024-10-01): one broadcast record per satellite, taken from a real file of another date and
// moved to the epoch.
//
// Moving a record (propagate_to_epoch): the record's own secular model is carried forward to the
// new reference time t_oe' = t_oe + D: the mean anomaly by the broadcast mean motion
// n = sqrt(mu / A^3) + delta_n, M0' = M0 + n D; the node by its broadcast rate, with the weekly
// reference of Omega0 moved to the new week (Omega_k = Omega0 + Omega_dot (t - t_oe)
// - Omega_e (t - week start) must be unchanged for all t, which gives
// Omega0' = Omega0 + Omega_dot D - Omega_e (week start' - week start)); i0, e, omega, the harmonic
// terms unchanged, IDOT = 0 (a 4-hour fit, meaningless over months). The clock polynomial keeps
// a_f0 and a_f1 at the new t_oc = t_oe' (a representative offset, not a prediction). The fit
// interval becomes the longest validate() accepts (240 h), so the record can be used for days.
//
// Error of the move, measured on real data (tests/gnss/test_constellation.cpp): the HERT file of
// 2024-04-01 moved 36 days to the epochs of the NYA1 file of 2024-05-07, against NYA1's own
// records: 74 km RMS, 166 km worst (of 20,200 km: 0.2-0.5 deg as seen from the Earth) over 152
// records. The error is along-track drift from the mean-motion error of the 4-hour fit and grows
// ~linearly: ~300 km RMS for the 147 days from 2024-05-07 to 2024-10-01. The result is a
// representative constellation, with realistic geometry and dynamics, not the satellites' real
// positions on that day (docs/algorithms/gnss-measurements.md#constellation-at-the-mission-epoch).

#include <optional>
#include <span>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/ephemeris_set.hpp"

namespace visors::gnss {

/// The record moved to t_oe' = new_toe (file comment).
BroadcastEphemeris propagate_to_epoch(const BroadcastEphemeris& record, core::GpsTime new_toe);

class GpsConstellation {
 public:
  /// For every PRN with a usable record, the one nearest source_time (EphemerisSet::nearest)
  /// moved to `epoch`. Error ("source_time") when the set has no usable record.
  static core::Result<GpsConstellation> from_broadcast(const EphemerisSet& set, core::GpsTime source_time,
                                                       core::GpsTime epoch);
  /// The given records as they are (they must pass validate(); the field names the record).
  static core::Result<GpsConstellation> from_records(std::span<const BroadcastEphemeris> records);

  /// The satellites, sorted by PRN.
  [[nodiscard]] std::span<const BroadcastEphemeris> satellites() const { return satellites_; }
  /// The record of `prn`, or nullptr.
  [[nodiscard]] const BroadcastEphemeris* satellite(int prn) const;

 private:
  std::vector<BroadcastEphemeris> satellites_;
};

}  // namespace visors::gnss
