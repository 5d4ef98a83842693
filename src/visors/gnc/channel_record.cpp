#include "visors/gnc/channel_record.hpp"

namespace visors::gnc {
namespace {

// Each message's channel is its place in RecordMessages (record_size() reads it so).
template <class... Message>
constexpr bool channels_in_order(std::tuple<Message...>*) {
  int c = 0;
  return ((static_cast<int>(RecordSchema<Message>::kChannel) == ++c) && ...);
}
static_assert(channels_in_order(static_cast<RecordMessages*>(nullptr)), "RecordMessages lists the messages in channel order");

}  // namespace

std::string_view to_string(Channel channel) {
  switch (channel) {
    case Channel::kTimeAtTone: return "time_at_tone";
    case Channel::kNavigation: return "navigation";
    case Channel::kCrosslink: return "crosslink";
    case Channel::kGroundCommand: return "ground_command";
    case Channel::kPropulsion: return "propulsion";
    case Channel::kGps: return "gps";
    case Channel::kLaserRange: return "laser_range";
    case Channel::kManeuver: return "maneuver";
    case Channel::kObservation: return "observation";
    case Channel::kTelemetry: return "telemetry";
    case Channel::kNavigationTelemetry: return "navigation_telemetry";
  }
  return "unknown";
}

std::string_view to_string(RecordStatus status) {
  switch (status) {
    case RecordStatus::kAccepted: return "accepted";
    case RecordStatus::kTruncated: return "truncated";
    case RecordStatus::kBadMagic: return "bad_magic";
    case RecordStatus::kUnknownChannel: return "unknown_channel";
    case RecordStatus::kWrongChannel: return "wrong_channel";
    case RecordStatus::kBadVersion: return "bad_version";
    case RecordStatus::kBadSize: return "bad_size";
    case RecordStatus::kBadChecksum: return "bad_checksum";
    case RecordStatus::kBadEnumeration: return "bad_enumeration";
    case RecordStatus::kBadPadding: return "bad_padding";
    case RecordStatus::kOutOfOrder: return "out_of_order";
  }
  return "unknown";
}

namespace record {

void write_header(Writer& w, Channel channel, core::GpsTime t, std::uint32_t sequence) {
  w.u8(kRecordMagic[0]);
  w.u8(kRecordMagic[1]);
  w.u8(static_cast<std::uint8_t>(channel));
  w.u8(kRecordVersion);
  w.u16(static_cast<std::uint16_t>(record_size(channel)));
  w.u16(0);
  w.time(t);
  w.u32(sequence);
}

RecordStatus read_frame(std::span<const std::uint8_t> in, Channel expected, RecordHeader& header) {
  if (in.size() < kHeaderBytes) return RecordStatus::kTruncated;
  Reader r(in, 0);
  if (r.u8() != kRecordMagic[0] || r.u8() != kRecordMagic[1]) return RecordStatus::kBadMagic;
  const std::uint8_t channel = r.u8();
  const std::uint8_t version = r.u8();
  const std::uint16_t size = r.u16();
  if (size < kHeaderBytes + kChecksumBytes || size > kMaxRecordBytes) return RecordStatus::kBadSize;
  if (in.size() < size) return RecordStatus::kTruncated;
  if (crc32c(in.first(size - kChecksumBytes)) != Reader(in, size - kChecksumBytes).u32()) return RecordStatus::kBadChecksum;
  if (channel < 1 || channel > kChannels) return RecordStatus::kUnknownChannel;
  if (channel != static_cast<std::uint8_t>(expected)) return RecordStatus::kWrongChannel;
  if (version != kRecordVersion) return RecordStatus::kBadVersion;
  if (size != record_size(expected)) return RecordStatus::kBadSize;
  if (r.u16() != 0) return RecordStatus::kBadPadding;  // reserved
  header.channel = expected;
  header.version = version;
  header.size = size;
  header.t = r.time();
  header.sequence = r.u32();
  return RecordStatus::kAccepted;
}

}  // namespace record

std::optional<Channel> channel_of(std::span<const std::uint8_t> in) {
  if (in.size() < kHeaderBytes || in[2] < 1 || in[2] > kChannels) return std::nullopt;
  return static_cast<Channel>(in[2]);
}

bool SequenceGate::would_admit(const RecordHeader& header) const {
  const auto c = static_cast<std::size_t>(header.channel);
  // Serial-number comparison (RFC 1982): ahead when the u32 difference, read signed, is > 0.
  return !seen_[c] || static_cast<std::int32_t>(header.sequence - last_[c]) > 0;
}

RecordStatus SequenceGate::admit(const RecordHeader& header) {
  if (!would_admit(header)) return RecordStatus::kOutOfOrder;
  const auto c = static_cast<std::size_t>(header.channel);
  seen_[c] = true;
  last_[c] = header.sequence;
  return RecordStatus::kAccepted;
}

}  // namespace visors::gnc
