#pragma once
// Every input the flight software refused, counted once, by one reason and by its channel
// (telemetry). Three places refuse an input, and their verdicts share one list of reasons:
//  - the binary interface, a record's bytes (RecordStatus: truncated .. out of order);
//  - the message's validation, a record's values (core::Problem: not finite .. not ready);
//  - the component, a valid input it cannot use (a step back in time, a navigation solution with
//    no orbit, a GPS epoch before any attitude).
// The reasons keep the order of the two enumerations they come from, so the mapping is an offset
// (checked below); a reason's index is what the telemetry record carries.

#include <array>
#include <cstdint>
#include <string_view>

#include "visors/core/status.hpp"
#include "visors/gnc/record_header.hpp"

namespace visors::gnc {

enum class RejectionReason : std::uint8_t {
  kNone,
  // The record's bytes (RecordStatus, in its order).
  kTruncated,
  kBadMagic,
  kUnknownChannel,
  kWrongChannel,
  kBadVersion,
  kBadSize,
  kBadChecksum,
  kBadEnumeration,
  kBadPadding,
  kOutOfOrder,
  // The record's values (core::Problem, in its order).
  kNotFinite,
  kOutOfRange,
  kTooOld,
  kInTheFuture,
  kNotUnit,
  kNotSymmetric,
  kRepeated,
  kInconsistent,
  kUnknown,
  kSingular,
  kNotConverged,
  kInfeasible,
  kCapacity,
  kNotReady,
  // A valid input the component cannot use.
  kTimeBackwards,  // the step's time is before the previous step's: nothing of the step is used
  kNoOrbit,        // a navigation solution whose states have no (elliptic) orbital elements
  kNoAttitude,     // a GPS epoch before any attitude to place the antenna with
};
inline constexpr int kRejectionReasons = 28;  // kNone .. kNoAttitude

/// The reason of a refused record (`status` not kAccepted).
constexpr RejectionReason rejection_reason(RecordStatus status) {
  return static_cast<RejectionReason>(static_cast<int>(status));
}
/// The reason of a refused value (`problem` not kNone).
constexpr RejectionReason rejection_reason(core::Problem problem) {
  return static_cast<RejectionReason>(static_cast<int>(RejectionReason::kOutOfOrder) + static_cast<int>(problem));
}
static_assert(rejection_reason(RecordStatus::kOutOfOrder) == RejectionReason::kOutOfOrder, "RecordStatus order");
static_assert(rejection_reason(core::Problem::kNotFinite) == RejectionReason::kNotFinite, "core::Problem order");
static_assert(rejection_reason(core::Problem::kNotReady) == RejectionReason::kNotReady, "core::Problem order");
static_assert(static_cast<int>(RejectionReason::kNoAttitude) + 1 == kRejectionReasons, "one counter per reason");

/// The reason's name, e.g. "bad_checksum", "too_old", "no_orbit".
std::string_view to_string(RejectionReason reason);

struct InputRejections {
  /// Inputs refused, by RejectionReason (index 0, kNone, unused).
  std::array<std::int64_t, kRejectionReasons> by_reason{};
  /// The same inputs by channel (index: Channel's value; 0 for a record whose channel is unknown:
  /// truncated, bad magic, unknown channel).
  std::array<std::int64_t, kChannels + 1> by_channel{};

  /// One refused input. `channel` 0 when unknown.
  void count(RejectionReason reason, int channel) {
    ++by_reason[static_cast<std::size_t>(reason)];
    ++by_channel[static_cast<std::size_t>(channel)];
  }
  void count(RejectionReason reason, Channel channel) { count(reason, static_cast<int>(channel)); }
  [[nodiscard]] std::int64_t of(RejectionReason reason) const { return by_reason[static_cast<std::size_t>(reason)]; }
  [[nodiscard]] std::int64_t of(Channel channel) const { return by_channel[static_cast<std::size_t>(channel)]; }
  [[nodiscard]] std::int64_t total() const;
  InputRejections& operator+=(const InputRejections& other);
};

}  // namespace visors::gnc
