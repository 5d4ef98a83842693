#pragma once
// Where a GPS user finds the broadcast record of a satellite at a time: the screened day of a
// navigation file on the ground (gnss/ephemeris_set.hpp), or the records decoded so far on board
// (gnss/ephemeris_store.hpp). The navigation filter and the point solution only select.

#include "visors/core/gps_time.hpp"
#include "visors/gnss/broadcast_ephemeris.hpp"

namespace visors::gnss {

class EphemerisSource {
 public:
  /// The record of `prn` to use at t, or nullptr when none is usable there. Allocation-free.
  [[nodiscard]] virtual const BroadcastEphemeris* select(int prn, core::GpsTime t) const = 0;

 protected:
  EphemerisSource() = default;
  EphemerisSource(const EphemerisSource&) = default;
  EphemerisSource& operator=(const EphemerisSource&) = default;
  ~EphemerisSource() = default;
};

}  // namespace visors::gnss
