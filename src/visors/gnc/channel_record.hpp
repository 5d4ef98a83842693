#pragma once
// The flight component's channels as fixed-size binary records (docs/record-layout.md): what a
// host application exchanges with it, and what the simulator passes through so that the loop
// exercises the codec.
//
// Record = header (20 bytes, gnc/record_header.hpp) + payload (fixed per channel and version) +
// CRC-32C (4 bytes) of header and payload (gnc/crc32c.hpp). Each payload is its message's field
// list (gnc/record_schema.hpp): encode() and decode() below walk that list, so there is no
// hand-written codec per channel, and the sizes are the lists' (at compile time).
//
// Decoding checks the structure only, in this order, and names the first failure
// (RecordStatus): header length, magic, declared size within bounds, length against it,
// checksum, channel known, channel the one decoded, version, size the channel's, reserved bytes,
// then the payload's fields in order (an enumeration, flag or count beyond its range, a padding
// or unused byte not 0). An accepted record is canonical: encoding what it decodes to gives back
// the same bytes (the fuzz target's property, fuzz/).
// The checksum comes before the channel and version: a corrupted byte reads as a bad checksum, and
// kWrongChannel means an intact record of another channel. The values (finite, plausible, not
// stale) are the messages' own validation (gnc/messages.hpp validate); the order of arrival is
// SequenceGate's. No allocation, no exception: flight code.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <tuple>

#include "visors/core/gps_time.hpp"
#include "visors/gnc/crc32c.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/gnc/record_fields.hpp"
#include "visors/gnc/record_header.hpp"
#include "visors/gnc/record_schema.hpp"

namespace visors::gnc {

/// A message that travels as a record: it has a field list (gnc/record_schema.hpp).
template <class Message>
concept RecordMessage = requires { RecordSchema<Message>::kChannel; };

/// The whole record's size of a channel [bytes] (0 for a number that is no channel).
[[nodiscard]] constexpr std::size_t record_size(Channel channel) {
  constexpr auto kPayload = []<class... Message>(std::tuple<Message...>*) {
    return std::array<std::size_t, kChannels + 1>{0, kPayloadBytes<Message>...};
  }(static_cast<RecordMessages*>(nullptr));
  const auto c = static_cast<std::size_t>(channel);
  return c >= 1 && c <= kChannels ? kHeaderBytes + kPayload[c] + kChecksumBytes : 0;
}
/// The largest record of any channel [bytes].
inline constexpr std::size_t kMaxRecordBytes = [] {
  std::size_t largest = 0;
  for (int c = 1; c <= kChannels; ++c) largest = std::max(largest, record_size(static_cast<Channel>(c)));
  return largest;
}();
using RecordBuffer = std::array<std::uint8_t, kMaxRecordBytes>;

namespace record {

/// The header's checks of the file comment, up to the payload (kAccepted: `header` holds it).
RecordStatus read_frame(std::span<const std::uint8_t> in, Channel expected, RecordHeader& header);
/// The header for `channel` with `t` and `sequence` (the checksum is written after the payload).
void write_header(Writer& w, Channel channel, core::GpsTime t, std::uint32_t sequence);

}  // namespace record

/// Writes the record of `message` with `sequence` into `out`; returns its size, or 0 when `out`
/// is too small (nothing written then).
template <RecordMessage Message>
std::size_t encode(const Message& message, std::uint32_t sequence, std::span<std::uint8_t> out) {
  using Schema = RecordSchema<Message>;
  constexpr std::size_t size = record_size(Schema::kChannel);
  if (out.size() < size) return 0;
  record::Writer w(out);
  record::write_header(w, Schema::kChannel, message.t, sequence);
  Schema::Payload::write(w, message, message);
  w.u32(crc32c(out.first(size - kChecksumBytes)));
  return size;
}

/// Reads a record of the message's channel from the start of `in` (extra bytes after it are
/// ignored). On kAccepted `message` and `header` hold it; otherwise they are unchanged.
template <RecordMessage Message>
RecordStatus decode(std::span<const std::uint8_t> in, Message& message, RecordHeader& header) {
  using Schema = RecordSchema<Message>;
  RecordHeader h;
  if (const RecordStatus s = record::read_frame(in, Schema::kChannel, h); s != RecordStatus::kAccepted) return s;
  record::Reader r(in, kHeaderBytes);
  Message m{};
  m.t = h.t;
  if (const RecordStatus s = Schema::Payload::read(r, m, m); s != RecordStatus::kAccepted) return s;
  if constexpr (requires { Schema::complete(m); }) Schema::complete(m);
  message = m;
  header = h;
  return RecordStatus::kAccepted;
}

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

}  // namespace visors::gnc
