#pragma once
// A day (or any span) of broadcast ephemeris records for the whole constellation, screened once,
// and the selection of the record to use at a given time.
//
// Screening (each record gets one status, the first that applies):
//   implausible  - validate() fails (a value no GPS orbit or clock can have);
//   inconsistent - the record disagrees with every other plausible record of the same PRN whose
//                  t_oe is within kNeighbourWindowS, while at least two of those agree with each
//                  other (or it has a single neighbour and they disagree: then both are marked,
//                  since which one is wrong cannot be told). Two records agree when, at the
//                  midpoint of their t_oe, their positions differ by less than kAgreementM and
//                  their clocks by less than kAgreementM / c. Consecutive uploads agree to a few
//                  metres; a record carrying another satellite's orbit differs by thousands of km.
//                  The health flag is not used here: an unhealthy neighbour still has a valid
//                  orbit to compare with (the case of PRN 1 in brdc1820.10n, see the tests);
//   unhealthy    - the SV health word is not 0;
//   usable       - otherwise.
// Health and plausibility alone miss the corrupt record of the 2010 IGS file: a healthy-flagged
// PRN 1 record at 06:00 that is 40,000 km away from the satellite.
//
// Selection: the usable record of the PRN with t_oe closest to t (on equal distance, the later
// transmission), if t is within its fit interval. Allocation-free.

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/ephemeris_source.hpp"

namespace visors::gnss {

enum class RecordStatus { kUsable, kUnhealthy, kImplausible, kInconsistent };

/// "usable", "unhealthy", "implausible", "inconsistent".
const char* to_string(RecordStatus status);

struct ScreenedEphemeris {
  BroadcastEphemeris ephemeris;
  RecordStatus status = RecordStatus::kUsable;
  std::string reason;          // why it is not usable (empty when usable)
  std::size_t source_line = 0;  // where it came from (file line of its first row; 0 = unknown)
};

class EphemerisSet final : public EphemerisSource {
 public:
  static constexpr double kNeighbourWindowS = 6.0 * 3600.0;
  static constexpr double kAgreementM = RecordDisagreement::kAgreementM;

  /// Screens the records (file comment); `source_lines`, if not empty, gives each record's line.
  static EphemerisSet screen(std::span<const BroadcastEphemeris> records,
                             std::span<const std::size_t> source_lines = {});

  /// The record to use at t (file comment), or nullptr when none is usable there.
  [[nodiscard]] const BroadcastEphemeris* select(int prn, core::GpsTime t) const override;
  /// The usable record of `prn` with t_oe nearest t, whether or not t is in its fit interval
  /// (to build a constellation from a station file that tracked each satellite part of the day).
  [[nodiscard]] const BroadcastEphemeris* nearest(int prn, core::GpsTime t) const;

  /// All records, sorted by PRN then t_oe then transmission time.
  [[nodiscard]] std::span<const ScreenedEphemeris> records() const { return records_; }
  [[nodiscard]] std::size_t count(RecordStatus status) const;

 private:
  std::vector<ScreenedEphemeris> records_;
  std::vector<std::size_t> first_of_prn_;  // records_[first_of_prn_[p], first_of_prn_[p + 1]) hold PRN p
};

}  // namespace visors::gnss
