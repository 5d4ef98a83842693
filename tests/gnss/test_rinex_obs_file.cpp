// RINEX 3 observation files: writer/reader round trip, a hand-written mixed-system file laid out
// after RINEX 3.05 section 5 (Tables A1-A3), and malformed input.
#include <cmath>

#include <gtest/gtest.h>

#include "gnss/files/rinex_obs_file.hpp"
#include "support/temp_file.hpp"

namespace visors::gnss::files {
namespace {

core::GpsTime gps(const char* iso) { return core::GpsTime::parse(iso, core::TimeScale::kGps).value(); }

ObservationFile sample_file() {
  ObservationFile f;
  f.header.marker_name = "OSC";
  f.header.comments = {"simulated receiver"};
  f.header.approx_position_m = {-1234567.8901, 2345678.9012, -6543210.0987};
  f.header.first_observation = gps("2024-10-01T00:00:00");
  f.header.antenna_delta_xyz_m = Eigen::Vector3d(0.0, 0.0, 0.1);
  f.header.antenna_boresight_xyz = Eigen::Vector3d::UnitZ();
  for (int k = 0; k < 3; ++k) {
    ObservationEpoch e;
    e.t = gps("2024-10-01T00:00:00") + static_cast<double>(k);
    e.receiver_clock_offset_s = k == 1 ? std::optional<double>() : std::optional<double>(1.234567890123e-6 * (k + 1));
    for (int prn : {2, 17, 32}) {
      SatelliteObservations s;
      s.prn = prn;
      s.values = {{2.1e7 + 1234.5678 * prn + k, 0, 7},
                  {1.1e8 + 0.125 * prn - 7 * k, prn == 17 && k == 2 ? 1 : 0, 7},
                  {-3456.789 * prn / 32.0, 0, 0},
                  {prn == 32 ? std::optional<double>() : std::optional<double>(44.25), 0, 0}};
      e.satellites.push_back(s);
    }
    f.epochs.push_back(e);
  }
  return f;
}

// Values survive to the format's 3 decimals (0.0005); flags, PRNs, times exactly.
TEST(RinexObs, WriteReadRoundTrip) {
  const ObservationFile original = sample_file();
  test::TempFile file("", ".rnx");
  ASSERT_TRUE(write_rinex3_observations(file.path(), original).ok());
  const auto again = read_rinex3_observations(file.path());
  ASSERT_TRUE(again.ok()) << again.error().describe();
  EXPECT_DOUBLE_EQ(again->version, 3.05);
  EXPECT_EQ(again->header.marker_name, "OSC");
  EXPECT_EQ(again->header.marker_type, "SPACEBORNE");
  EXPECT_EQ(again->header.observation_types, original.header.observation_types);
  EXPECT_EQ(again->header.first_observation, original.header.first_observation);
  EXPECT_NEAR((again->header.approx_position_m - original.header.approx_position_m).norm(), 0.0, 1e-4);
  ASSERT_TRUE(again->header.antenna_delta_xyz_m.has_value());
  EXPECT_DOUBLE_EQ(again->header.antenna_delta_xyz_m->z(), 0.1);
  ASSERT_TRUE(again->header.antenna_boresight_xyz.has_value());
  EXPECT_DOUBLE_EQ(again->header.antenna_boresight_xyz->z(), 1.0);
  ASSERT_EQ(again->epochs.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    const auto& a = original.epochs[k];
    const auto& b = again->epochs[k];
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.receiver_clock_offset_s.has_value(), b.receiver_clock_offset_s.has_value());
    if (a.receiver_clock_offset_s) {
      EXPECT_NEAR(*a.receiver_clock_offset_s, *b.receiver_clock_offset_s, 1e-12);
    }
    ASSERT_EQ(b.satellites.size(), 3u);
    for (std::size_t s = 0; s < 3; ++s) {
      EXPECT_EQ(a.satellites[s].prn, b.satellites[s].prn);
      for (std::size_t v = 0; v < 4; ++v) {
        const auto& x = a.satellites[s].values[v];
        const auto& y = b.satellites[s].values[v];
        ASSERT_EQ(x.value.has_value(), y.value.has_value());
        if (x.value) {
          EXPECT_NEAR(*x.value, *y.value, 5e-4);
        }
        EXPECT_EQ(x.lli, y.lli);
        EXPECT_EQ(x.ssi, y.ssi);
      }
    }
  }
}

// A hand-written file in the layout of RINEX 3.05 section 5 (header labels in columns 61-80, a
// continuation line of SYS / # / OBS TYPES, a Galileo system line and record to skip, an event
// record with flag 4 and one comment line).
TEST(RinexObs, ReadsAMixedSystemFile) {
  const std::string text =
      "     3.04           OBSERVATION DATA    M: MIXED            RINEX VERSION / TYPE\n"
      "test                                                        PGM / RUN BY / DATE\n"
      "HERT                                                        MARKER NAME\n"
      "G   15 C1C L1C D1C S1C C2W L2W S2W C5Q L5Q D5Q S5Q C1L L1L  SYS / # / OBS TYPES\n"
      "       D1L S1L                                              SYS / # / OBS TYPES\n"
      "E    2 C1C L1C                                              SYS / # / OBS TYPES\n"
      "  2024     4     1     0     0    0.0000000     GPS         TIME OF FIRST OBS\n"
      "                                                            END OF HEADER\n"
      "> 2024 04 01 00 00  0.0000000  0  2\n"
      "G05  21234567.123 7 111586123.456 7     -1234.567 7        45.000  \n"
      "E11  23456789.012 6 123456789.012 6\n"
      "> 2024 04 01 00 00  1.0000000  4  1\n"
      "a comment inside an event record                            COMMENT\n"
      "> 2024 04 01 00 00  2.0000000  0  1\n"
      "G05  21234767.123 7 111587174.45617\n";
  test::TempFile file(text, ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  EXPECT_EQ(obs->header.observation_types.size(), 15u);
  EXPECT_EQ(obs->header.observation_types.back(), "S1L");
  ASSERT_EQ(obs->epochs.size(), 2u);
  ASSERT_EQ(obs->epochs[0].satellites.size(), 1u);  // E11 skipped
  const auto& g05 = obs->epochs[0].satellites[0];
  EXPECT_EQ(g05.prn, 5);
  EXPECT_DOUBLE_EQ(*g05.values[0].value, 21234567.123);
  EXPECT_EQ(g05.values[0].ssi, 7);
  EXPECT_DOUBLE_EQ(*g05.values[3].value, 45.0);
  EXPECT_FALSE(g05.values[4].value.has_value());  // C2W absent (short line)
  EXPECT_EQ(obs->epochs[1].t, gps("2024-04-01T00:00:02"));
  EXPECT_EQ(obs->epochs[1].satellites[0].values[1].lli, 1);
  EXPECT_DOUBLE_EQ(*obs->epochs[1].satellites[0].values[1].value, 111587174.456);
}

std::string minimal_header() {
  return "     3.05           OBSERVATION DATA    G: GPS              RINEX VERSION / TYPE\n"
         "G    2 C1C L1C                                              SYS / # / OBS TYPES\n"
         "                                                            END OF HEADER\n";
}

TEST(RinexObs, TruncatedEpochNamesFileAndLine) {
  test::TempFile file(minimal_header() + "> 2024 10 01 00 00  0.0000000  0  3\nG01  21234567.123   111586123.456\n", ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":5");
  EXPECT_NE(obs.error().message.find("truncated"), std::string::npos) << obs.error().message;
}

TEST(RinexObs, BadValueNamesTypeAndColumns) {
  test::TempFile file(minimal_header() + "> 2024 10 01 00 00  0.0000000  0  1\nG01  21234567.1x3   111586123.456\n", ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":5");
  EXPECT_NE(obs.error().message.find("C1C (columns 4-17)"), std::string::npos) << obs.error().message;
}

TEST(RinexObs, BadEpochLine) {
  test::TempFile file(minimal_header() + "> 2024 13 01 00 00  0.0000000  0  0\n", ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":4");
}

TEST(RinexObs, Version2IsRejected) {
  test::TempFile file("     2.11           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n", ".05o");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":1");
}

TEST(RinexObs, NoGpsTypesIsAnError) {
  test::TempFile file("     3.05           OBSERVATION DATA    E: GALILEO          RINEX VERSION / TYPE\n"
                      "E    2 C1C L1C                                              SYS / # / OBS TYPES\n"
                      "                                                            END OF HEADER\n",
                      ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":3");
}

TEST(RinexObs, WriterRejectsValuesThatDoNotFit) {
  ObservationFile f = sample_file();
  f.epochs[1].satellites[2].values[1].value = 2e10;
  test::TempFile file("", ".rnx");
  const auto ok = write_rinex3_observations(file.path(), f);
  ASSERT_FALSE(ok.ok());
  EXPECT_EQ(ok.error().field, "epoch 2024-10-01T00:00:01.000.G32");
}

// The receiver record as RINEX: C1C, L1C (LLI 1 after a loss of lock), D1C, S1C, SSI from C/N0.
TEST(RinexObs, MeasurementEpochConversion) {
  GpsMeasurementEpoch m;
  m.t = gps("2024-10-01T00:00:05");
  m.channel_count = 1;
  m.channels[0] = {7, 2.2e7, 1.15e8, -1200.0, 47.5, true, 0.0};
  const ObservationEpoch e = to_observation_epoch(m, 3e-7);
  ASSERT_EQ(e.satellites.size(), 1u);
  EXPECT_EQ(e.satellites[0].prn, 7);
  EXPECT_EQ(e.satellites[0].values[1].lli, 1);
  EXPECT_EQ(e.satellites[0].values[0].ssi, 7);  // RINEX 3.05: 42-47 dB-Hz -> 7
  EXPECT_DOUBLE_EQ(*e.satellites[0].values[3].value, 47.5);
}

}  // namespace
}  // namespace visors::gnss::files
