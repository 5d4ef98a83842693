// The flight component behind its binary channels (gnc/record_interface.hpp): records of any
// channel dispatched by their header, garbage and older records refused and counted by reason,
// the newest record of a channel used, the outputs as records; and a deterministic mutation
// test: a day of valid input records, each mutated (bit flips, truncations, overwritten bytes,
// swapped channels, stale and NaN values), never crashes the component or leaks a NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "formation_harness.hpp"
#include "visors/gnc/record_interface.hpp"

namespace visors::gnc {
namespace {

const core::GpsTime kT0 = core::GpsTime::from_seconds(1.4e9);

RecordInterface make(Spacecraft self = Spacecraft::kOsc, bool active = true) {
  GncConfig config;
  config.self = self;
  config.active = active;
  return RecordInterface::create(config).value();
}

struct Encoded {
  RecordBuffer bytes{};
  std::size_t size = 0;
  [[nodiscard]] RecordView view() const { return {bytes.data(), size}; }
};

template <class Message>
Encoded record(const Message& m, std::uint32_t sequence) {
  Encoded e;
  e.size = encode(m, sequence, e.bytes);
  return e;
}

// The harness's inputs of step k as records (sequence k), plus extra ones.
std::vector<Encoded> step_records(const test::FormationHarness& h, int k) {
  const GncInputs in = h.inputs(k);
  return {record(*in.time_at_tone, static_cast<std::uint32_t>(k)), record(*in.navigation, static_cast<std::uint32_t>(k))};
}

std::vector<RecordView> views(const std::vector<Encoded>& records) {
  std::vector<RecordView> out;
  for (const Encoded& r : records) out.push_back(r.view());
  return out;
}

Telemetry telemetry_of(const OutputRecords& out) {
  Telemetry tm;
  RecordHeader h;
  EXPECT_EQ(decode(out.telemetry.view(), tm, h), RecordStatus::kAccepted);
  return tm;
}

std::int64_t refused(const Telemetry& tm, RecordStatus s) { return tm.rejected.of(rejection_reason(s)); }

TEST(RecordInterface, ACommandRecordChangesTheMode) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  std::vector<Encoded> records = step_records(h, 0);
  records.push_back(record(GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0}, 0));
  const Telemetry tm = telemetry_of(gnc.step(kT0, views(records)));
  EXPECT_EQ(tm.mode, Mode::kStandby);
  EXPECT_TRUE(tm.estimate_valid);
  EXPECT_EQ(tm.rejected.total(), 0);
}

TEST(RecordInterface, GarbageIsRefusedAndCountedByReason) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  std::vector<Encoded> records = step_records(h, 0);
  Encoded short_one;
  short_one.size = 5;
  Encoded no_magic = records[0];
  no_magic.bytes[0] = 'X';
  Encoded flipped = records[1];
  flipped.bytes[100] ^= 0x04;
  records.insert(records.end(), {short_one, no_magic, flipped});
  const Telemetry tm = telemetry_of(gnc.step(kT0, views(records)));
  EXPECT_EQ(refused(tm, RecordStatus::kTruncated), 1);
  EXPECT_EQ(refused(tm, RecordStatus::kBadMagic), 1);
  EXPECT_EQ(refused(tm, RecordStatus::kBadChecksum), 1);
  EXPECT_TRUE(tm.estimate_valid);  // the intact records were used
}

// A host's u32 sequence numbers wrap (after 2^32 records of a channel: 136 years at 1 Hz, sooner
// for a host that numbers all its records in one counter): steps whose records' sequences run
// from 2^32 - 5 through 0 to 4 are all admitted (serial-number arithmetic, RFC 1982).
TEST(RecordInterface, RecordsAreAdmittedAcrossTheSequenceWrap) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  Telemetry tm;
  for (int k = 0; k < 10; ++k) {
    const GncInputs in = h.inputs(k);
    const std::uint32_t sequence = 0xFFFFFFFBu + static_cast<std::uint32_t>(k);  // 2^32 - 5, ..., 4
    std::vector<Encoded> records = {record(*in.time_at_tone, sequence), record(*in.navigation, sequence)};
    if (k == 0) records.push_back(record(GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0}, sequence));
    tm = telemetry_of(gnc.step(kT0 + static_cast<double>(k), views(records)));
  }
  EXPECT_EQ(tm.rejected.total(), 0);
  EXPECT_TRUE(tm.estimate_valid);
}

// An output channel's record is not an input.
TEST(RecordInterface, AnOutputRecordAsInputIsTheWrongChannel) {
  RecordInterface gnc = make();
  const std::vector<Encoded> records = {record(ManeuverCommand{kT0, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()}, 0)};
  EXPECT_EQ(refused(telemetry_of(gnc.step(kT0, views(records))), RecordStatus::kWrongChannel), 1);
}

// Nor is the navigation telemetry, an output too.
TEST(RecordInterface, ANavigationTelemetryRecordAsInputIsTheWrongChannel) {
  RecordInterface gnc = make();
  NavigationTelemetry m;
  m.t = kT0;
  const std::vector<Encoded> records = {record(m, 0)};
  EXPECT_EQ(refused(telemetry_of(gnc.step(kT0, views(records))), RecordStatus::kWrongChannel), 1);
}

// A record older than the last admitted of its channel is refused.
TEST(RecordInterface, AnOlderRecordIsRefused) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  std::vector<Encoded> records = step_records(h, 0);
  records.push_back(record(GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0}, 5));
  (void)gnc.step(kT0, views(records));
  std::vector<Encoded> next = step_records(h, 1);
  next.push_back(record(GroundCommand{kT0 + 1.0, GroundCommand::Kind::kToManual, 0}, 4));  // older
  const Telemetry tm = telemetry_of(gnc.step(kT0 + 1.0, views(next)));
  EXPECT_EQ(refused(tm, RecordStatus::kOutOfOrder), 1);
  EXPECT_EQ(tm.mode, Mode::kStandby);
}

// Of two records of a channel in one step the newer is used: standby (5), then back to manual (6).
TEST(RecordInterface, TheNewestRecordOfAChannelIsUsed) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  std::vector<Encoded> records = step_records(h, 0);
  records.push_back(record(GroundCommand{kT0, GroundCommand::Kind::kToStandby, 0}, 5));
  (void)gnc.step(kT0, views(records));
  std::vector<Encoded> next = step_records(h, 1);
  next.push_back(record(GroundCommand{kT0 + 1.0, GroundCommand::Kind::kToStandby, 0}, 7));
  next.push_back(record(GroundCommand{kT0 + 1.0, GroundCommand::Kind::kToManual, 0}, 8));
  EXPECT_EQ(telemetry_of(gnc.step(kT0 + 1.0, views(next))).mode, Mode::kManual);
}

TEST(RecordInterface, EveryStepHasATelemetryRecordAndACrosslinkRecord) {
  RecordInterface gnc = make();
  const OutputRecords& out = gnc.step(kT0, {});
  EXPECT_EQ(out.telemetry.size, record_size(Channel::kTelemetry));
  CrosslinkMessage crosslink;
  RecordHeader h;
  EXPECT_EQ(decode(out.crosslink.view(), crosslink, h), RecordStatus::kAccepted);
  EXPECT_EQ(crosslink.sender, Spacecraft::kOsc);
  EXPECT_EQ(out.navigation.size, 0u);  // no on-board navigation, no navigation telemetry
}

// The deterministic mutation test (file comment): 3,000 steps, every record of each mutated with
// probability 1/2 in one of six ways; the component never refuses to step, its outputs always
// decode and hold no NaN, and every mutated record is either refused (counted) or its values
// refused by validation, or it is harmless.
TEST(RecordInterface, MutatedRecordsNeverBreakTheComponent) {
  RecordInterface gnc = make();
  test::FormationHarness h(test::mission_chief(), test::roe_m(0, 0, 0, 200, 0, 200), kT0);
  std::mt19937_64 rng(16);
  std::int64_t mutated = 0;
  for (int k = 0; k < 3000; ++k) {
    const core::GpsTime t = kT0 + static_cast<double>(k);
    std::vector<Encoded> records = step_records(h, k);
    if (k == 0) records.push_back(record(GroundCommand{t, GroundCommand::Kind::kToStandby, 0}, 0));
    if (k % 97 == 0) records.push_back(record(PropulsionTelemetry{t, Eigen::Vector3d(NAN, 0, 0), 10.0, true}, k));
    for (Encoded& r : records) {
      if (rng() % 2 == 0) continue;
      ++mutated;
      switch (rng() % 6) {
        case 0: r.bytes[rng() % r.size] ^= static_cast<std::uint8_t>(1u << (rng() % 8)); break;
        case 1: r.size = rng() % r.size; break;
        case 2: r.bytes[rng() % r.size] = static_cast<std::uint8_t>(rng()); break;
        case 3: r.bytes[2] = static_cast<std::uint8_t>(rng() % 16); break;
        case 4: r = record(TimeAtTone{t - 100.0, Eigen::Quaterniond::Identity()}, static_cast<std::uint32_t>(k)); break;
        default: r = record(TimeAtTone{t, Eigen::Quaterniond(NAN, 0, 0, 0)}, static_cast<std::uint32_t>(k)); break;
      }
    }
    const OutputRecords& out = gnc.step(t, views(records));
    const Telemetry tm = telemetry_of(out);
    ASSERT_TRUE(tm.roe_mean_m.allFinite()) << "step " << k;
    ASSERT_TRUE(std::isfinite(tm.safety_margin_m)) << "step " << k;
  }
  const Telemetry tm = telemetry_of(gnc.step(kT0 + 3000.0, {}));
  EXPECT_GT(mutated, 2500);
  EXPECT_GT(tm.rejected.total(), mutated / 2);
  EXPECT_EQ(tm.mode, Mode::kStandby);
}

// The tone (RecordInterface::tone): what a flight software process steps at.
TEST(RecordInterfaceTone, IsTheTimeTagOfTheTimeAtToneRecord) {
  const RecordInterface rif = make();
  const auto records = std::vector<Encoded>{record(LaserRange{kT0 - 1.0, 40.0}, 0),
                                            record(TimeAtTone{kT0 + 3.0, Eigen::Quaterniond::Identity()}, 0)};
  EXPECT_EQ(rif.tone(views(records)), kT0 + 3.0);
}

TEST(RecordInterfaceTone, IsNoneWithoutATimeAtToneRecord) {
  const RecordInterface rif = make();
  EXPECT_FALSE(rif.tone(views({record(LaserRange{kT0, 40.0}, 0)})).has_value());
}

// A corrupted time-at-tone record (bad checksum) carries no time: the next intact one does.
TEST(RecordInterfaceTone, SkipsATimeAtToneRecordThatDoesNotDecode) {
  const RecordInterface rif = make();
  auto records = std::vector<Encoded>{record(TimeAtTone{kT0 + 7.0, Eigen::Quaterniond::Identity()}, 0),
                                      record(TimeAtTone{kT0 + 1.0, Eigen::Quaterniond::Identity()}, 1)};
  records[0].bytes[kHeaderBytes] ^= 0x01;
  EXPECT_EQ(rif.tone(views(records)), kT0 + 1.0);
}

// A replayed time-at-tone record (its sequence not after the last admitted one) is no tone.
TEST(RecordInterfaceTone, SkipsATimeAtToneRecordTheSequenceGateRefuses) {
  RecordInterface rif = make();
  const auto first = std::vector<Encoded>{record(TimeAtTone{kT0, Eigen::Quaterniond::Identity()}, 5)};
  rif.step(kT0, views(first));
  const auto next = std::vector<Encoded>{record(TimeAtTone{kT0 + 9.0, Eigen::Quaterniond::Identity()}, 5),
                                         record(TimeAtTone{kT0 + 1.0, Eigen::Quaterniond::Identity()}, 6)};
  EXPECT_EQ(rif.tone(views(next)), kT0 + 1.0);
}

// The time of a record whose attitude validation refuses (the garbage fault's NaN) is still the
// tone: the time tag is intact.
TEST(RecordInterfaceTone, IsTheTimeOfARecordWithARefusedAttitude) {
  const RecordInterface rif = make();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto records = std::vector<Encoded>{record(TimeAtTone{kT0 + 2.0, Eigen::Quaterniond(nan, 0.0, 0.0, 0.0)}, 0)};
  EXPECT_EQ(rif.tone(views(records)), kT0 + 2.0);
}

}  // namespace
}  // namespace visors::gnc
