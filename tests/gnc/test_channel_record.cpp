// The flight component's binary records (gnc/channel_record.hpp) and their checksum
// (gnc/crc32c.hpp): the checksum against RFC 3720's vectors, the byte layout pinned by hand, every
// message through encode and decode, and every malformed record refused with its reason: each
// single-bit flip, each truncation, other channels, versions and enumerations, random garbage.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "gnc/channel_record.hpp"
#include "gnc/crc32c.hpp"

namespace visors::gnc {
namespace {

std::vector<std::uint8_t> bytes(std::initializer_list<int> values) {
  std::vector<std::uint8_t> out;
  for (int v : values) out.push_back(static_cast<std::uint8_t>(v));
  return out;
}

// RFC 3720 (iSCSI) sec. B.4 and the usual check value; the same from a bit-by-bit Python
// evaluation of the reflected polynomial 0x82F63B78.
TEST(Crc32c, CheckValue) {
  const std::string text = "123456789";
  EXPECT_EQ(crc32c(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size())), 0xE3069283u);
}

TEST(Crc32c, Rfc3720Zeros) { EXPECT_EQ(crc32c(std::vector<std::uint8_t>(32, 0x00)), 0x8A9136AAu); }

TEST(Crc32c, Rfc3720Ones) { EXPECT_EQ(crc32c(std::vector<std::uint8_t>(32, 0xFF)), 0x62A8AB43u); }

TEST(Crc32c, Rfc3720Incrementing) {
  std::vector<std::uint8_t> v(32);
  for (int i = 0; i < 32; ++i) v[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
  EXPECT_EQ(crc32c(v), 0x46DD794Eu);
}

core::GpsTime t0() { return core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value(); }

TimeAtTone tone() { return {t0() + 1.5, Eigen::Quaterniond(0.5, -0.5, 0.5, 0.5)}; }

NavigationSolution navigation() {
  NavigationSolution m;
  m.t = t0() + 2.0;
  m.chief_gcrf = {Eigen::Vector3d(6878137.0, -1.5, 2.25), Eigen::Vector3d(0.1, 7612.6, -0.2)};
  m.deputy_gcrf = {Eigen::Vector3d(6878140.0, 39.0, 3.0), Eigen::Vector3d(0.1, 7612.61, -0.21)};
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) m.relative_covariance_rtn(i, j) = 1e-6 * (1 + i + j) + (i == j ? 1e-4 : 0.0);
  }
  return m;
}

CrosslinkMessage crosslink() {
  CrosslinkMessage m;
  m.t = t0() + 3.0;
  m.sender = Spacecraft::kOsc;
  m.mode = Mode::kScience;
  m.sender_active = true;
  m.observations_done = 3;
  m.observations_planned = 10;
  m.has_observation = true;
  m.observation_index = 4;
  m.slew_start = t0() + 100.0;
  m.observation_start = t0() + 250.0;
  m.observation_end = t0() + 260.0;
  return m;
}

GroundCommand command() { return {t0() + 4.0, GroundCommand::Kind::kStartScience, 10}; }

PropulsionTelemetry propulsion() { return {t0() + 5.0, Eigen::Vector3d(0.001, -0.002, 0.0005), 11.2, true}; }

// The header and payload of a ground command, written out by hand from the layout of the file
// comment: the record is exactly these bytes plus their CRC-32C.
TEST(ChannelRecord, GroundCommandLayoutByHand) {
  RecordBuffer buffer{};
  const GroundCommand m{core::GpsTime::from_nanoseconds(0x0102030405060708), GroundCommand::Kind::kEscape, -2};
  ASSERT_EQ(encode(m, 0xA0B0C0D0u, buffer), 32u);
  const std::vector<std::uint8_t> expected = bytes({'V', 'G', 4, 1, 32, 0, 0, 0,                  // magic, channel, version, size, reserved
                                                    0x08, 0x07, 0x06, 0x05, 0x04, 0x03, 0x02, 0x01,  // time tag
                                                    0xD0, 0xC0, 0xB0, 0xA0,                          // sequence
                                                    4, 0, 0, 0, 0xFE, 0xFF, 0xFF, 0xFF});          // kind, padding, -2
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), buffer.begin()));
  const std::uint32_t crc = crc32c(std::span<const std::uint8_t>(expected));
  EXPECT_EQ(buffer[28] | buffer[29] << 8 | buffer[30] << 16 | static_cast<std::uint32_t>(buffer[31]) << 24, crc);
}

// Encoded as a record of `channel` and decoded back.
template <class Message>
Message round_trip(const Message& m, Channel channel, std::uint32_t sequence, RecordHeader& header) {
  RecordBuffer buffer{};
  const std::size_t n = encode(m, sequence, buffer);
  EXPECT_EQ(n, record_size(channel));
  Message out{};
  EXPECT_EQ(decode(std::span(buffer).first(n), out, header), RecordStatus::kAccepted);
  return out;
}

TEST(ChannelRecord, TimeAtToneRoundTrip) {
  RecordHeader h;
  const TimeAtTone out = round_trip(tone(), Channel::kTimeAtTone, 7, h);
  EXPECT_EQ(out.t, tone().t);
  EXPECT_EQ(out.q_body_to_gcrf.coeffs(), tone().q_body_to_gcrf.coeffs());
  EXPECT_EQ(h.sequence, 7u);
}

TEST(ChannelRecord, NavigationRoundTrip) {
  RecordHeader h;
  const NavigationSolution out = round_trip(navigation(), Channel::kNavigation, 8, h);
  EXPECT_EQ(out.t, navigation().t);
  EXPECT_EQ(out.chief_gcrf.r, navigation().chief_gcrf.r);
  EXPECT_EQ(out.deputy_gcrf.v, navigation().deputy_gcrf.v);
  EXPECT_EQ(out.relative_covariance_rtn, navigation().relative_covariance_rtn);  // symmetric: the upper triangle suffices
}

TEST(ChannelRecord, CrosslinkRoundTrip) {
  RecordHeader h;
  const CrosslinkMessage out = round_trip(crosslink(), Channel::kCrosslink, 9, h);
  const CrosslinkMessage in = crosslink();
  EXPECT_EQ(out.sender, in.sender);
  EXPECT_EQ(out.mode, in.mode);
  EXPECT_EQ(out.sender_active, in.sender_active);
  EXPECT_EQ(out.observations_done, in.observations_done);
  EXPECT_EQ(out.observations_planned, in.observations_planned);
  EXPECT_EQ(out.has_observation, in.has_observation);
  EXPECT_EQ(out.observation_index, in.observation_index);
  EXPECT_EQ(out.slew_start, in.slew_start);
  EXPECT_EQ(out.observation_start, in.observation_start);
  EXPECT_EQ(out.observation_end, in.observation_end);
}

TEST(ChannelRecord, GroundCommandRoundTrip) {
  RecordHeader h;
  const GroundCommand out = round_trip(command(), Channel::kGroundCommand, 10, h);
  EXPECT_EQ(out.kind, command().kind);
  EXPECT_EQ(out.observations, command().observations);
}

TEST(ChannelRecord, PropulsionRoundTrip) {
  RecordHeader h;
  const PropulsionTelemetry out = round_trip(propulsion(), Channel::kPropulsion, 11, h);
  EXPECT_EQ(out.dv_body_mps, propulsion().dv_body_mps);
  EXPECT_EQ(out.mass_kg, propulsion().mass_kg);
  EXPECT_EQ(out.executed, propulsion().executed);
}

TEST(ChannelRecord, EncodeRefusesASmallBuffer) {
  std::array<std::uint8_t, 20> small{};
  EXPECT_EQ(encode(navigation(), 1, small), 0u);
}

// Every single-bit flip of every record is refused (CRC-32C detects all of them; the header's
// checks may name another reason first), and leaves the output untouched.
template <class Message>
int accepted_flips(const Message& m) {
  RecordBuffer buffer{};
  const std::size_t n = encode(m, 1, buffer);
  int accepted = 0;
  for (std::size_t byte = 0; byte < n; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      RecordBuffer bad = buffer;
      bad[byte] ^= static_cast<std::uint8_t>(1u << bit);
      Message out{};
      RecordHeader h;
      accepted += decode(std::span(bad).first(n), out, h) == RecordStatus::kAccepted ? 1 : 0;
    }
  }
  return accepted;
}

TEST(ChannelRecord, EveryBitFlipIsRefused) {
  EXPECT_EQ(accepted_flips(tone()), 0);
  EXPECT_EQ(accepted_flips(navigation()), 0);
  EXPECT_EQ(accepted_flips(crosslink()), 0);
  EXPECT_EQ(accepted_flips(command()), 0);
  EXPECT_EQ(accepted_flips(propulsion()), 0);
}

TEST(ChannelRecord, EveryTruncationIsNamed) {
  RecordBuffer buffer{};
  const std::size_t n = encode(navigation(), 1, buffer);
  int truncated = 0;
  for (std::size_t length = 0; length < n; ++length) {
    NavigationSolution out;
    RecordHeader h;
    truncated += decode(std::span(buffer).first(length), out, h) == RecordStatus::kTruncated ? 1 : 0;
  }
  EXPECT_EQ(truncated, static_cast<int>(n));
}

// A record re-sealed with a valid checksum after a change: the reason is the change's.
template <class Message>
RecordStatus resealed(const Message& m, std::size_t offset, std::uint8_t value) {
  RecordBuffer buffer{};
  const std::size_t n = encode(m, 1, buffer);
  buffer[offset] = value;
  const std::uint32_t crc = crc32c(std::span<const std::uint8_t>(buffer).first(n - kChecksumBytes));
  for (int i = 0; i < 4; ++i) buffer[n - 4 + static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(crc >> (8 * i));
  Message out{};
  RecordHeader h;
  return decode(std::span(buffer).first(n), out, h);
}

TEST(ChannelRecord, AnotherVersionIsNamed) { EXPECT_EQ(resealed(tone(), 3, 2), RecordStatus::kBadVersion); }

TEST(ChannelRecord, AnUnknownChannelIsNamed) { EXPECT_EQ(resealed(tone(), 2, 9), RecordStatus::kUnknownChannel); }

TEST(ChannelRecord, AnUnknownModeIsNamed) { EXPECT_EQ(resealed(crosslink(), kHeaderBytes + 1, 6), RecordStatus::kBadEnumeration); }

TEST(ChannelRecord, AnUnknownCommandIsNamed) { EXPECT_EQ(resealed(command(), kHeaderBytes, 7), RecordStatus::kBadEnumeration); }

TEST(ChannelRecord, ABooleanOtherThanZeroOrOneIsNamed) {
  EXPECT_EQ(resealed(propulsion(), kHeaderBytes + 32, 2), RecordStatus::kBadEnumeration);
}

TEST(ChannelRecord, ANonZeroReservedByteIsNamed) { EXPECT_EQ(resealed(tone(), 6, 1), RecordStatus::kBadPadding); }

TEST(ChannelRecord, ANonZeroPaddingByteIsNamed) {
  EXPECT_EQ(resealed(propulsion(), kHeaderBytes + 39, 1), RecordStatus::kBadPadding);
}

TEST(ChannelRecord, AnIntactRecordOfAnotherChannelIsNamed) {
  RecordBuffer buffer{};
  const std::size_t n = encode(tone(), 1, buffer);
  NavigationSolution out;
  RecordHeader h;
  EXPECT_EQ(decode(std::span(buffer).first(n), out, h), RecordStatus::kWrongChannel);
}

TEST(ChannelRecord, ABadMagicIsNamed) {
  RecordBuffer buffer{};
  const std::size_t n = encode(tone(), 1, buffer);
  buffer[0] = 'X';
  TimeAtTone out;
  RecordHeader h;
  EXPECT_EQ(decode(std::span(buffer).first(n), out, h), RecordStatus::kBadMagic);
}

// Garbage: 100,000 random buffers (seeded), half of them with the right magic and a plausible
// size, none accepted (2^-32 per buffer at most); every reason counted.
TEST(ChannelRecord, RandomGarbageIsNeverAccepted) {
  std::mt19937_64 rng(2026);
  std::uniform_int_distribution<int> byte(0, 255);
  RecordCounters counters;
  for (int k = 0; k < 100000; ++k) {
    RecordBuffer buffer{};
    const std::size_t length = static_cast<std::size_t>(rng() % (kMaxRecordBytes + 1));
    for (std::size_t i = 0; i < length; ++i) buffer[i] = static_cast<std::uint8_t>(byte(rng));
    if (k % 2 == 0 && length >= kHeaderBytes) {
      buffer[0] = 'V';
      buffer[1] = 'G';
      buffer[4] = static_cast<std::uint8_t>(record_size(Channel::kNavigation));
      buffer[5] = static_cast<std::uint8_t>(record_size(Channel::kNavigation) >> 8);
    }
    NavigationSolution out;
    RecordHeader h;
    counters.count(decode(std::span(buffer).first(length), out, h));
  }
  EXPECT_EQ(counters.by_status[static_cast<std::size_t>(RecordStatus::kAccepted)], 0);
  EXPECT_EQ(counters.refused(), 100000);
  EXPECT_GT(counters.by_status[static_cast<std::size_t>(RecordStatus::kBadChecksum)], 0);
}

// The values are the messages' own validation: a NaN travels intact and validate() refuses it.
TEST(ChannelRecord, ANanTravelsAndValidationRefusesIt) {
  PropulsionTelemetry m = propulsion();
  m.mass_kg = std::nan("");
  RecordHeader h;
  const PropulsionTelemetry out = round_trip(m, Channel::kPropulsion, 1, h);
  EXPECT_TRUE(std::isnan(out.mass_kg));
  EXPECT_FALSE(validate(out, m.t).ok());
}

RecordHeader header(Channel c, std::uint32_t sequence) {
  RecordHeader h;
  h.channel = c;
  h.sequence = sequence;
  return h;
}

TEST(SequenceGate, AdmitsTheNextAndRefusesARepeat) {
  SequenceGate gate;
  EXPECT_EQ(gate.admit(header(Channel::kCrosslink, 5)), RecordStatus::kAccepted);
  EXPECT_EQ(gate.admit(header(Channel::kCrosslink, 6)), RecordStatus::kAccepted);
  EXPECT_EQ(gate.admit(header(Channel::kCrosslink, 6)), RecordStatus::kOutOfOrder);
}

TEST(SequenceGate, RefusesAnOlderRecordAndKeepsTheNewest) {
  SequenceGate gate;
  (void)gate.admit(header(Channel::kNavigation, 10));
  EXPECT_EQ(gate.admit(header(Channel::kNavigation, 9)), RecordStatus::kOutOfOrder);
  EXPECT_EQ(gate.admit(header(Channel::kNavigation, 11)), RecordStatus::kAccepted);
}

TEST(SequenceGate, AdmitsAGapAndTheWrap) {
  SequenceGate gate;
  (void)gate.admit(header(Channel::kTimeAtTone, 0xFFFFFFF0u));
  EXPECT_EQ(gate.admit(header(Channel::kTimeAtTone, 0xFFFFFFFFu)), RecordStatus::kAccepted);  // 15 lost
  EXPECT_EQ(gate.admit(header(Channel::kTimeAtTone, 2u)), RecordStatus::kAccepted);            // wrapped
}

TEST(SequenceGate, ChannelsAreIndependent) {
  SequenceGate gate;
  (void)gate.admit(header(Channel::kTimeAtTone, 100));
  EXPECT_EQ(gate.admit(header(Channel::kPropulsion, 1)), RecordStatus::kAccepted);
}

}  // namespace
}  // namespace visors::gnc
