#pragma once
// The frame every channel record shares (docs/record-layout.md): its header's constants, the
// channels, and why a record is refused. The payloads are gnc/record_schema.hpp's.
//
// Record = header (20 bytes) + payload (fixed per channel and version) + CRC-32C (4 bytes) of
// header and payload (gnc/crc32c.hpp). Every number little-endian. Header:
//   0  magic      2 bytes 'V' 'G'
//   2  channel    u8 (Channel)
//   3  version    u8 (kRecordVersion)
//   4  size       u16, the whole record [bytes]
//   6  reserved   u16, 0
//   8  time tag   i64 [GPS ns]: the message's own time (its `t`)
//   16 sequence   u32, per channel and sender, +1 per record (wraps)

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "visors/core/gps_time.hpp"

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
/// The channel's name, e.g. "time_at_tone", "gps".
std::string_view to_string(Channel channel);
/// The two bytes every record starts with.
inline constexpr std::array<std::uint8_t, 2> kRecordMagic{'V', 'G'};
inline constexpr std::uint8_t kRecordVersion = 3;  // 3: the telemetry's one set of input rejections
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

}  // namespace visors::gnc
