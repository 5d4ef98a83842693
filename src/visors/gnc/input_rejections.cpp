#include "visors/gnc/input_rejections.hpp"

#include <numeric>

namespace visors::gnc {

std::string_view to_string(RejectionReason reason) {
  switch (reason) {
    case RejectionReason::kNone: return "none";
    case RejectionReason::kTruncated: return "truncated";
    case RejectionReason::kBadMagic: return "bad_magic";
    case RejectionReason::kUnknownChannel: return "unknown_channel";
    case RejectionReason::kWrongChannel: return "wrong_channel";
    case RejectionReason::kBadVersion: return "bad_version";
    case RejectionReason::kBadSize: return "bad_size";
    case RejectionReason::kBadChecksum: return "bad_checksum";
    case RejectionReason::kBadEnumeration: return "bad_enumeration";
    case RejectionReason::kBadPadding: return "bad_padding";
    case RejectionReason::kOutOfOrder: return "out_of_order";
    case RejectionReason::kNotFinite: return "not_finite";
    case RejectionReason::kOutOfRange: return "out_of_range";
    case RejectionReason::kTooOld: return "too_old";
    case RejectionReason::kInTheFuture: return "in_the_future";
    case RejectionReason::kNotUnit: return "not_unit";
    case RejectionReason::kNotSymmetric: return "not_symmetric";
    case RejectionReason::kRepeated: return "repeated";
    case RejectionReason::kInconsistent: return "inconsistent";
    case RejectionReason::kUnknown: return "unknown_value";
    case RejectionReason::kSingular: return "singular";
    case RejectionReason::kNotConverged: return "not_converged";
    case RejectionReason::kInfeasible: return "infeasible";
    case RejectionReason::kCapacity: return "capacity";
    case RejectionReason::kNotReady: return "not_ready";
    case RejectionReason::kTimeBackwards: return "time_backwards";
    case RejectionReason::kNoOrbit: return "no_orbit";
    case RejectionReason::kNoAttitude: return "no_attitude";
  }
  return "unknown_reason";
}

std::int64_t InputRejections::total() const { return std::accumulate(by_reason.begin(), by_reason.end(), std::int64_t{0}); }

InputRejections& InputRejections::operator+=(const InputRejections& other) {
  for (std::size_t k = 0; k < by_reason.size(); ++k) by_reason[k] += other.by_reason[k];
  for (std::size_t k = 0; k < by_channel.size(); ++k) by_channel[k] += other.by_channel[k];
  return *this;
}

}  // namespace visors::gnc
