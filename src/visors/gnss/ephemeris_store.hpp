#pragma once
// The broadcast ephemerides a spacecraft has decoded so far (flight side): the receiver hands
// over each record as it decodes it (the flight component's GPS message), and the store keeps the
// newest kRecordsPerPrn per satellite, so that the record in use and the one replacing it at a
// data-set change (IS-GPS-200: every 2 h) are both at hand. Fixed capacity, allocation-free.
//
// Acceptance of a record (the first failure is the answer, AcceptStatus):
//   implausible  - validate() fails (a value no GPS orbit or clock can have);
//   unhealthy    - the SV health word is not 0: stored all the same (never selected), as the
//                  neighbour the next check compares with;
//   duplicate    - a stored record has the same t_oe and IODE (a repeat of the broadcast);
//   stale        - older (t_oe) than every stored record of a full slot set;
//   inconsistent - a stored record of the same PRN with t_oe within
//                  kNeighbourWindowS disagrees with it at their midpoint by
//                  RecordDisagreement::kAgreementM or more (position or c x clock): the record carries
//                  another orbit (the corrupt record of the 2010 IGS file was 40,000 km off).
//                  The stored one, accepted first and used since, is kept: on board one
//                  neighbour cannot say which is wrong, and a good record of the next data set
//                  is accepted as usual once the bad one has aged out.
// Selection: as EphemerisSet::select (the healthy stored record with t_oe nearest t, the later
// transmission on a tie, if t is within its fit interval).

#include <array>
#include <cstdint>

#include "visors/gnss/broadcast_ephemeris.hpp"
#include "visors/gnss/ephemeris_source.hpp"
#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

class EphemerisStore final : public EphemerisSource {
 public:
  static constexpr int kRecordsPerPrn = 2;
  static constexpr double kNeighbourWindowS = 6.0 * 3600.0;  // as EphemerisSet

  enum class AcceptStatus : std::uint8_t { kStored, kImplausible, kUnhealthy, kDuplicate, kStale, kInconsistent };

  /// Stores `record` unless one of the checks of the file comment refuses it.
  AcceptStatus accept(const BroadcastEphemeris& record);

  [[nodiscard]] const BroadcastEphemeris* select(int prn, core::GpsTime t) const override;
  /// Records stored for `prn` (0 for a PRN out of 1..32).
  [[nodiscard]] int count(int prn) const;
  /// Satellites with at least one record.
  [[nodiscard]] int satellites() const;

 private:
  struct Slots {
    std::array<BroadcastEphemeris, kRecordsPerPrn> records{};
    int count = 0;
  };
  std::array<Slots, kMaxGpsPrn + 1> by_prn_{};
};

const char* to_string(EphemerisStore::AcceptStatus status);

}  // namespace visors::gnss
