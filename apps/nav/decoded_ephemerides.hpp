#pragma once
// The broadcast records one receiver had decoded by a time, for the replay of `visors nav`: on
// board, a spacecraft's navigation has a data set only from when its own receiver has decoded it
// (subframes 1-3 received whole after the lock or the set's first broadcast, 18-36 s:
// sim/navigation_message.hpp), never from the ground's navigation file. gnss-sim writes, per
// receiver, the epoch at which it decoded each set (ephemeris_decoded.csv); the records themselves
// are brdc.rnx's.
//
// Selection as gnss::EphemerisSet::select, among the usable records (the file's screening) the
// receiver had decoded at or before t: the one with t_oe nearest t (on equal distance the later
// one), if t is within its fit interval. So a set that has just started being broadcast is used
// from its decoding on, the previous one (if decoded) until then; a satellite whose sets the
// receiver never decoded has none for the first 18-36 s of its lock.

#include <array>
#include <span>
#include <string>
#include <vector>

#include "visors/core/gps_time.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/ephemeris_source.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::nav_app {

/// One row of ephemeris_decoded.csv for a receiver: the data set (PRN, t_oe) and the time tag of
/// the first epoch at which the receiver had decoded it.
struct DecodedDataSet {
  int prn = 0;
  core::GpsTime toe;
  core::GpsTime decoded;
};

class DecodedEphemerides final : public gnss::EphemerisSource {
 public:
  DecodedEphemerides() = default;

  /// The records of `screened` that `decoded` lists; a listed set that is not among them is an
  /// error naming `file` (the run's files do not belong together). Records screened out
  /// (unhealthy, implausible, inconsistent) are never selected, as from EphemerisSet.
  static core::Result<DecodedEphemerides> create(const gnss::EphemerisSet& screened, std::span<const DecodedDataSet> decoded,
                                                 const std::string& file);

  [[nodiscard]] const gnss::BroadcastEphemeris* select(int prn, core::GpsTime t) const override;

 private:
  struct Entry {
    gnss::BroadcastEphemeris record;
    core::GpsTime decoded;
  };
  std::array<std::vector<Entry>, gnss::kMaxGpsPrn + 1> by_prn_;  // in the screened set's order (t_oe)
};

}  // namespace visors::nav_app
