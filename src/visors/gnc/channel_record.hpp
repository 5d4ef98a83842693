#pragma once
// The flight component's channels as fixed-size binary records
// (docs/architecture.md#binary-records): what a host application exchanges with it, and what the
// simulator passes through so that the loop exercises the codec.
//
// Record = header (20 bytes) + payload (fixed per channel and version) + CRC-32C (4 bytes) of
// header and payload (gnc/crc32c.hpp). Every number little-endian; doubles as their IEEE 754
// bits; times as GPS nanoseconds (core::GpsTime). Header:
//   0  magic      2 bytes 'V' 'G'
//   2  channel    u8 (Channel)
//   3  version    u8 (kRecordVersion)
//   4  size       u16, the whole record [bytes]
//   6  reserved   u16, 0
//   8  time tag   i64 [GPS ns]: the message's own time (its `t`)
//   16 sequence   u32, per channel and sender, +1 per record (wraps)
// Payloads (offsets from the payload's start):
//   time at tone   q_body_to_gcrf w, x, y, z (4 f64)                                       32
//   navigation     chief r, v; deputy r, v (GCRF; 12 f64); relative covariance RTN, upper
//                  triangle row by row (21 f64)                                            264
//   crosslink      sender, mode, sender_active, has_observation (4 u8); observations_done,
//                  observations_planned, observation_index (3 i32); slew_start,
//                  observation_start, observation_end (3 i64 ns); navigation (below)       456
//   ground command kind (u8), 3 bytes 0, observations (i32)                               8
//   propulsion     dv_body (3 f64), mass (f64), executed (u8), 7 bytes 0                  40
//   GPS            channel count, has_ephemeris (2 u8), 6 bytes 0; 12 channels of: prn, flags
//                  (bit 0 loss of lock, bit 1 half cycle) (2 u8), 6 bytes 0, pseudorange,
//                  carrier phase, Doppler, C/N0, lock time (5 f64) (unused channels all 0);
//                  the broadcast record (gnss::BroadcastEphemeris, all 0 without one):
//                  prn, iode, iodc, health (4 i32), toc, toe, transmission (3 i64 ns),
//                  af0, af1, af2, sqrt_a, e, i0, omega0, omega, m0, delta_n, idot, omega_dot,
//                  cuc, cus, crc, crs, cic, cis, tgd, ura, fit interval (21 f64)         792
//   laser range    range (f64)                                                            8
//   maneuver       dv_body, dv_rtn (6 f64)                                               48
//   observation    index (i32), 4 bytes 0, slew_start, start, end (3 i64 ns)              32
//   telemetry      mode, active, estimate_valid, safety_checked, star_tracker_power,
//                  lrf_power, gnc_incapable, passive_safety_violated (8 u8); a * mean ROE
//                  (6 f64), safety margin (f64), a * target ROE (6 f64), observations_done,
//                  pending_pieces (2 i32), plans, planning_failures (2 i64), rejected by
//                  channel (7 i64), records refused by status (11 i64), navigation_valid,
//                  navigation_fixed, drag_valid (3 u8), 5 bytes 0, navigation_update
//                  (i64 ns), differential drag (f64)                                    304
//   navigation     has_solution, valid, fixed, fix_applied, full_fix (5 u8), dd_count,
//   telemetry      dd_reference_prn, combination_count (3 u8); update_t (i64 ns); DSC r, v;
//                  OSC r, v (GCRF; 12 f64); p DSC, p OSC (body; 6 f64); empirical DSC, OSC
//                  (RTN; 6 f64); relative sigma RTN (3 f64); 11 double differences of prn
//                  (u8), 7 bytes 0, integer_cycles (i64), fixed_cycles (f64) (unused all 0);
//                  11 fixed combinations of 11 dd_coefficients (i32; 0 beyond dd_count),
//                  4 bytes 0, integer_cycles (i64) (unused all 0); counters: epochs joint,
//                  alone, refused, fixed, wrong fixes refused, impulses applied, late, laser
//                  used, rejected, clock jumps (10 i64), ephemerides by status (6 i64)      1240
// The crosslink's payload goes on after its 40 bytes above with the navigation part
// (CrosslinkNavigation): has_epoch, impulse_count, has_range, epoch count (4 u8), 4 bytes 0;
// epoch time tag (i64 ns); 12 observations of prn, flags (2 u8), 6 bytes 0, code, phase (2 f64)
// (unused all 0); attitude w, x, y, z (4 f64); 2 impulses of t (i64 ns), dv GCRF (3 f64)
// (unused all 0); range t (i64 ns), range (f64): 456 in all.
//
// Decoding checks the structure only, in this order, and names the first failure
// (RecordStatus): header length, magic, declared size within bounds, length against it,
// checksum, channel known, channel the one decoded, version, size the channel's, reserved bytes,
// enumerations and padding. An accepted record is canonical: encoding what it decodes to gives
// back the same bytes (the fuzz target's property, fuzz/).
// The checksum comes before the channel and version: a corrupted byte reads as a bad checksum, and
// kWrongChannel means an intact record of another channel. The values
// (finite, plausible, not stale) are the messages' own validation (gnc/messages.hpp validate);
// the order of arrival is SequenceGate's. No allocation, no exception: flight code.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <span>
#include <tuple>
#include <string_view>

#include "visors/core/gps_time.hpp"
#include "visors/gnc/messages.hpp"

namespace visors::gnc {

enum class Channel : std::uint8_t {
  // Inputs.
  kTimeAtTone = 1,
  kNavigation = 2,
  kCrosslink = 3,  // also an output (the host forwards it to the other spacecraft)
  kGroundCommand = 4,
  kPropulsion = 5,
  kGps = 6,
  kLaserRange = 7,
  // Outputs.
  kManeuver = 8,
  kObservation = 9,
  kTelemetry = 10,
  kNavigationTelemetry = 11,  // with on-board navigation (NavigationTelemetry)
};
inline constexpr int kChannels = 11;
/// The two bytes every record starts with.
inline constexpr std::array<std::uint8_t, 2> kRecordMagic{'V', 'G'};
inline constexpr std::uint8_t kRecordVersion = 2;  // 2: the navigation telemetry's fixed combinations
inline constexpr std::size_t kHeaderBytes = 20;
inline constexpr std::size_t kChecksumBytes = 4;

/// Why a record was refused (or kAccepted), for the telemetry's counters.
enum class RecordStatus : std::uint8_t {
  kAccepted,
  kTruncated,       // shorter than its header, or than the size it declares
  kBadMagic,
  kUnknownChannel,
  kWrongChannel,    // a valid record of another channel than the one decoded
  kBadVersion,
  kBadSize,         // the declared size is not the channel's
  kBadChecksum,
  kBadEnumeration,  // an enumerated field out of its range
  kBadPadding,      // a reserved or padding byte not 0
  kOutOfOrder,      // sequence not after the last accepted one (SequenceGate)
};
inline constexpr int kRecordStatuses = 11;
std::string_view to_string(RecordStatus status);

struct RecordHeader {
  Channel channel = Channel::kTimeAtTone;
  std::uint8_t version = 0;
  std::uint16_t size = 0;
  core::GpsTime t;
  std::uint32_t sequence = 0;
};

/// The whole record's size of a channel [bytes].
[[nodiscard]] constexpr std::size_t record_size(Channel channel) {
  constexpr std::size_t kPayload[] = {0, 32, 264, 456, 8, 40, 792, 8, 48, 32, 304, 1240};
  static_assert(std::size(kPayload) == kChannels + 1, "one payload size per channel");
  return kHeaderBytes + kPayload[static_cast<std::size_t>(channel)] + kChecksumBytes;
}
/// The largest record of any channel [bytes].
inline constexpr std::size_t kMaxRecordBytes = [] {
  std::size_t largest = 0;
  for (int c = 1; c <= kChannels; ++c) largest = std::max(largest, record_size(static_cast<Channel>(c)));
  return largest;
}();
using RecordBuffer = std::array<std::uint8_t, kMaxRecordBytes>;

/// Writes the record of `message` with `sequence` into `out`; returns its size, or 0 when `out`
/// is too small (nothing written then).
std::size_t encode(const TimeAtTone& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const NavigationSolution& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const CrosslinkMessage& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const GroundCommand& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const PropulsionTelemetry& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const GpsMessage& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const LaserRange& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const ManeuverCommand& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const ObservationCommand& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const Telemetry& message, std::uint32_t sequence, std::span<std::uint8_t> out);
std::size_t encode(const NavigationTelemetry& message, std::uint32_t sequence, std::span<std::uint8_t> out);

/// Reads a record of the message's channel from the start of `in` (extra bytes after it are
/// ignored). On kAccepted `message` and `header` hold it; otherwise they are unchanged.
RecordStatus decode(std::span<const std::uint8_t> in, TimeAtTone& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, NavigationSolution& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, CrosslinkMessage& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, GroundCommand& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, PropulsionTelemetry& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, GpsMessage& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, LaserRange& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, ManeuverCommand& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, ObservationCommand& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, Telemetry& message, RecordHeader& header);
RecordStatus decode(std::span<const std::uint8_t> in, NavigationTelemetry& message, RecordHeader& header);

/// The channel a record says it is of (its header's byte), without any other check: for a host
/// or an interface that dispatches records of any channel to their decode(). nullopt when `in`
/// is shorter than a header or the byte is no channel.
std::optional<Channel> channel_of(std::span<const std::uint8_t> in);

/// The order of arrival per channel: a record is admitted when its sequence number follows the
/// last admitted one of its channel (serial-number arithmetic, RFC 1982: within 2^31 ahead, so
/// the u32 may wrap); the first of each channel is always admitted. A repeated or older record
/// is kOutOfOrder and changes nothing.
class SequenceGate {
 public:
  RecordStatus admit(const RecordHeader& header);
  /// Whether admit() would admit it (nothing changes).
  [[nodiscard]] bool would_admit(const RecordHeader& header) const;

 private:
  std::array<std::uint32_t, kChannels + 1> last_{};
  std::array<bool, kChannels + 1> seen_{};
};

/// One refused (or accepted) record counted by its status (RecordCounters: messages.hpp).
inline void count(RecordCounters& counters, RecordStatus status) { ++counters.by_status[static_cast<std::size_t>(status)]; }
static_assert(std::tuple_size_v<decltype(RecordCounters::by_status)> == kRecordStatuses, "one counter per status");

}  // namespace visors::gnc
