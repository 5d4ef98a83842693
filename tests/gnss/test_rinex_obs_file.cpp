// RINEX 3 observation files: writer/reader round trip (values to the format's 3 decimals, flags,
// PRNs and times exactly), header round trip, hand-written files laid out after RINEX 3.05 section
// 5 and Appendix Tables A1 (header) and A2 (data records), and malformed input (every error names
// "<path>:<line>" with the exact line).
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "visors/gnss/files/rinex_obs_file.hpp"
#include "gnss_test_data.hpp"
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
  // RINEX 3.05 APPROX POSITION XYZ is 3F14.4 (1e-4 m); measured 0 (2026-11)
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
      // RINEX 3.05 receiver clock offset F15.12 (1e-12 s); measured 3.3e-13 s (2026-11)
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
  EXPECT_EQ(ok.error().field, "epoch 2024-10-01T00:00:01.000.G32.L1C");
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

// Every header field the writer emits comes back; 15 types use a continuation line (13 per line);
// the first observation keeps its 0.1 us fraction exactly.
TEST(RinexObsHeader, RoundTrip) {
  ObservationHeader h;
  h.program = "gnss-sim";
  h.run_by = "VISORS GNC";
  h.creation_date = "20241001 120000 UTC";
  h.marker_name = "DEPUTY";
  h.observer = "sim";
  h.agency = "VISORS consortium";
  h.receiver_number = "SN42";
  h.receiver_type = "LEO-GPS";
  h.receiver_version = "3.1";
  h.antenna_number = "ANT7";
  h.antenna_type = "PATCH L1";
  h.approx_position_m = {6878137.1234, -12.5, 0.0001};
  h.antenna_delta_hen_m = {0.1, 0.0, -0.05};
  h.observation_types = {"C1C", "L1C", "D1C", "S1C", "C2W", "L2W", "D2W", "S2W", "C5Q",
                         "L5Q", "D5Q", "S5Q", "C1L", "L1L", "S1L"};
  h.interval_s = 10.0;
  h.first_observation = gps("2024-10-01T12:34:56") + 0.1234567;
  h.comments = {"first comment", "second comment"};
  test::TempFile file("", ".rnx");
  ASSERT_TRUE(write_rinex3_observations(file.path(), h, std::span<const ObservationEpoch>()).ok());
  const auto back = read_rinex3_observations(file.path());
  ASSERT_TRUE(back.ok()) << back.error().describe();
  const ObservationHeader& r = back->header;
  EXPECT_EQ(r.program, h.program);
  EXPECT_EQ(r.run_by, h.run_by);
  EXPECT_EQ(r.creation_date, h.creation_date);
  EXPECT_EQ(r.marker_name, h.marker_name);
  EXPECT_EQ(r.marker_type, "SPACEBORNE");
  EXPECT_EQ(r.observer, h.observer);
  EXPECT_EQ(r.agency, h.agency);
  EXPECT_EQ(r.receiver_number, h.receiver_number);
  EXPECT_EQ(r.receiver_type, h.receiver_type);
  EXPECT_EQ(r.receiver_version, h.receiver_version);
  EXPECT_EQ(r.antenna_number, h.antenna_number);
  EXPECT_EQ(r.antenna_type, h.antenna_type);
  // RINEX 3.05 header fields F14.4: half a unit of the last digit, 5e-5 m; measured 0 (2026-11)
  EXPECT_LT((r.approx_position_m - h.approx_position_m).cwiseAbs().maxCoeff(), 5e-5);
  EXPECT_LT((r.antenna_delta_hen_m - h.antenna_delta_hen_m).cwiseAbs().maxCoeff(), 5e-5);
  EXPECT_FALSE(r.antenna_delta_xyz_m.has_value());
  EXPECT_EQ(r.observation_types, h.observation_types);
  EXPECT_DOUBLE_EQ(r.interval_s, 10.0);
  EXPECT_EQ(r.first_observation, h.first_observation);
  EXPECT_EQ(r.comments, h.comments);
  EXPECT_TRUE(back->epochs.empty());
  // The labels RINEX 3.05 Table A1 requires, in columns 61-80.
  const std::string text = test::file_text(file.path());
  for (const char* label : {"RINEX VERSION / TYPE", "PGM / RUN BY / DATE", "MARKER NAME", "MARKER TYPE",
                            "OBSERVER / AGENCY", "REC # / TYPE / VERS", "ANT # / TYPE", "APPROX POSITION XYZ",
                            "ANTENNA: DELTA H/E/N", "SYS / # / OBS TYPES", "INTERVAL", "TIME OF FIRST OBS",
                            "END OF HEADER"}) {
    EXPECT_NE(text.find(label), std::string::npos) << label;
  }
  EXPECT_EQ(text.substr(0, 80), "     3.05           OBSERVATION DATA    G: GPS              RINEX VERSION / TYPE");
  EXPECT_NE(text.find("  2024    10     1    12    34   56.1234567     GPS         TIME OF FIRST OBS"), std::string::npos);
}

// The streaming writer: epoch by epoch; a rejected epoch writes nothing and the file stays valid;
// epoch times keep 0.1 us and round (with carry into the next minute); F14.3 extremes.
TEST(RinexObs, StreamingWriterEpochByEpoch) {
  ObservationHeader h;
  h.observation_types = {"C1C", "L1C"};
  h.first_observation = gps("2024-10-01T00:00:00");
  test::TempFile file("", ".rnx");
  auto opened = Rinex3ObservationWriter::open(file.path(), h);
  ASSERT_TRUE(opened.ok()) << opened.error().describe();
  Rinex3ObservationWriter writer = std::move(opened).value();
  const core::GpsTime t0 = gps("2024-10-01T00:00:00");
  ObservationEpoch e1{t0 + 0.1234567, 0, 2.5e-4, {{1, {{9999999999.999, 0, 9}, {-999999999.999, 7, 1}}}}};
  ASSERT_TRUE(writer.write(e1).ok());
  ObservationEpoch bad{t0 + 1.0, 0, {}, {{3, {{2.0e7, 8, 0}, {1.0e8, 0, 0}}}}};  // LLI 8
  const auto rejected = writer.write(bad);
  ASSERT_FALSE(rejected.ok());
  EXPECT_EQ(rejected.error().field, "epoch 2024-10-01T00:00:01.000.G03.C1C");
  ObservationEpoch e2{t0 + 59.99999996, 1, {}, {{3, {{2.0e7, 0, 0}, {std::nullopt, 0, 0}}}}};
  ASSERT_TRUE(writer.write(e2).ok());
  ASSERT_TRUE(writer.close().ok());
  EXPECT_FALSE(writer.write(e1).ok());  // after close
  const auto back = read_rinex3_observations(file.path());
  ASSERT_TRUE(back.ok()) << back.error().describe();
  ASSERT_EQ(back->epochs.size(), 2u);
  EXPECT_EQ(back->epochs[0].t, t0 + 0.1234567);
  // 12 decimals of F15.12 hold 2.5e-4 exactly; measured 0 (2026-11)
  EXPECT_NEAR(*back->epochs[0].receiver_clock_offset_s, 2.5e-4, 1e-15);
  EXPECT_NEAR(*back->epochs[0].satellites[0].values[0].value, 9999999999.999, 5e-4);
  EXPECT_NEAR(*back->epochs[0].satellites[0].values[1].value, -999999999.999, 5e-4);
  EXPECT_EQ(back->epochs[0].satellites[0].values[1].lli, 7);
  EXPECT_EQ(back->epochs[0].satellites[0].values[1].ssi, 1);
  EXPECT_EQ(back->epochs[1].t, gps("2024-10-01T00:01:00"));  // 59.99999996 s rounds to the minute
  EXPECT_EQ(back->epochs[1].flag, 1);
  EXPECT_FALSE(back->epochs[1].receiver_clock_offset_s.has_value());
  EXPECT_FALSE(back->epochs[1].satellites[0].values[1].value.has_value());
}

TEST(RinexObs, WriterRejectsFieldsThatDoNotFit) {
  const auto rejected = [](ObservationFile f) {
    test::TempFile file("", ".rnx");
    const auto ok = write_rinex3_observations(file.path(), f);
    return ok.ok() ? std::string("accepted") : ok.error().field;
  };
  ObservationFile f = sample_file();
  f.epochs[0].satellites[1].values[2].value = -1.0e9;  // "-1000000000.000" is 15 characters
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:00.000.G17.D1C");
  f = sample_file();
  f.epochs[0].satellites[0].values[0].value = std::nan("");
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:00.000.G02.C1C");
  f = sample_file();
  f.epochs[2].receiver_clock_offset_s = -12.0;  // F15.12: "-12.000000000000" is 16 characters
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:02.000.receiver_clock_offset_s");
  f = sample_file();
  f.epochs[0].satellites[0].prn = 33;
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:00.000.G33");
  f = sample_file();
  f.epochs[0].satellites[0].values.pop_back();
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:00.000.G02");
  f = sample_file();
  f.epochs[0].flag = 4;
  EXPECT_EQ(rejected(f), "epoch 2024-10-01T00:00:00.000.flag");
  f = sample_file();
  f.header.observation_types[1] = "L1";
  EXPECT_EQ(rejected(f), "observation_types");
}

// A GPS-only RINEX 3.05 file written by hand after section 5 and Tables A1/A2: every required
// header label, an epoch with receiver clock offset (F15.12, columns 42-56), LLI and SSI digits,
// a blank value, "G 7" (a blank instead of the leading zero, as some converters write), an event
// record (flag 4: header lines follow), a power-failure epoch (flag 1, kept), a cycle-slip record
// (flag 6, skipped) and an epoch without satellites.
TEST(RinexObs, ReadsAHandWrittenGpsFile) {
  const std::string text =
      "     3.05           OBSERVATION DATA    G: GPS              RINEX VERSION / TYPE\n"
      "sim2rnx 1.0         VISORS              20241001 000512 UTC PGM / RUN BY / DATE\n"
      "OSC-A                                                       MARKER NAME\n"
      "SPACEBORNE                                                  MARKER TYPE\n"
      "ops                 VISORS team                             OBSERVER / AGENCY\n"
      "0001                LEO-GPS             2.1                 REC # / TYPE / VERS\n"
      "A01                 PATCH L1                                ANT # / TYPE\n"
      "  4510731.1234 -4510731.5678        0.0000                  APPROX POSITION XYZ\n"
      "        0.0000        0.0000        0.0000                  ANTENNA: DELTA H/E/N\n"
      "G    4 C1C L1C D1C S1C                                      SYS / # / OBS TYPES\n"
      "    10.000                                                  INTERVAL\n"
      "  2024    10     1     0     0    0.0000000     GPS         TIME OF FIRST OBS\n"
      "                                                            END OF HEADER\n"
      "> 2024 10 01 00 00  0.0000000  0  3      -0.000012345678\n"
      "G05  21234567.123 7 111586123.45617     -1234.567 7        45.250 7\n"
      "G12  23456789.012 6 123265432.109 6      2345.678 6        38.500 6\n"
      "G 7  24000000.000 5                         0.000 5        31.000 5\n"
      "> 2024 10 01 00 00  5.0000000  4  2\n"
      "  4510731.1234 -4510731.5678        0.0000                  APPROX POSITION XYZ\n"
      "header information follows an event flag 4                  COMMENT\n"
      "> 2024 10 01 00 00 10.0000000  1  1\n"
      "G05  21234767.123 7 111587174.456       -1234.000          45.000\n"
      "> 2024 10 01 00 00 10.0000000  6  1\n"
      "G05                 111587174.4561\n"
      "> 2024 10 01 00 00 20.0000000  0  0\n";
  test::TempFile file(text, ".rnx");
  const auto obs = read_rinex3_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  const ObservationHeader& h = obs->header;
  EXPECT_DOUBLE_EQ(obs->version, 3.05);
  EXPECT_EQ(h.program, "sim2rnx 1.0");
  EXPECT_EQ(h.run_by, "VISORS");
  EXPECT_EQ(h.creation_date, "20241001 000512 UTC");
  EXPECT_EQ(h.marker_name, "OSC-A");
  EXPECT_EQ(h.agency, "VISORS team");
  EXPECT_EQ(h.receiver_type, "LEO-GPS");
  EXPECT_EQ(h.receiver_version, "2.1");
  EXPECT_EQ(h.antenna_type, "PATCH L1");
  EXPECT_DOUBLE_EQ(h.approx_position_m.y(), -4510731.5678);
  EXPECT_EQ(h.observation_types, (std::vector<std::string>{"C1C", "L1C", "D1C", "S1C"}));
  EXPECT_DOUBLE_EQ(h.interval_s, 10.0);
  EXPECT_EQ(h.first_observation, gps("2024-10-01T00:00:00"));
  ASSERT_EQ(obs->epochs.size(), 3u);
  const ObservationEpoch& e0 = obs->epochs[0];
  EXPECT_EQ(e0.t, gps("2024-10-01T00:00:00"));
  EXPECT_EQ(e0.flag, 0);
  EXPECT_DOUBLE_EQ(*e0.receiver_clock_offset_s, -0.000012345678);
  ASSERT_EQ(e0.satellites.size(), 3u);
  EXPECT_EQ(e0.satellites[0].prn, 5);
  EXPECT_DOUBLE_EQ(*e0.satellites[0].values[1].value, 111586123.456);
  EXPECT_EQ(e0.satellites[0].values[1].lli, 1);
  EXPECT_EQ(e0.satellites[0].values[1].ssi, 7);
  EXPECT_DOUBLE_EQ(*e0.satellites[0].values[2].value, -1234.567);
  EXPECT_DOUBLE_EQ(*e0.satellites[0].values[3].value, 45.25);
  EXPECT_EQ(e0.satellites[1].prn, 12);
  EXPECT_EQ(e0.satellites[1].values[0].lli, 0);
  EXPECT_EQ(e0.satellites[1].values[0].ssi, 6);
  EXPECT_EQ(e0.satellites[2].prn, 7);
  EXPECT_FALSE(e0.satellites[2].values[1].value.has_value());
  EXPECT_DOUBLE_EQ(*e0.satellites[2].values[2].value, 0.0);
  const ObservationEpoch& e1 = obs->epochs[1];
  EXPECT_EQ(e1.t, gps("2024-10-01T00:00:10"));
  EXPECT_EQ(e1.flag, 1);
  EXPECT_FALSE(e1.receiver_clock_offset_s.has_value());
  ASSERT_EQ(e1.satellites.size(), 1u);
  EXPECT_EQ(e1.satellites[0].values[1].ssi, 0);  // blank = unknown
  EXPECT_DOUBLE_EQ(*e1.satellites[0].values[3].value, 45.0);
  EXPECT_EQ(obs->epochs[2].t, gps("2024-10-01T00:00:20"));
  EXPECT_TRUE(obs->epochs[2].satellites.empty());
}

// Each malformed input: the error names "<path>:<line>" (minimal_header() is lines 1-3).
struct Malformed {
  std::string text;
  int line;
  std::string message_part;
};

TEST(RinexObs, MalformedInputNamesFileAndLine) {
  const std::string h = minimal_header();
  const std::vector<Malformed> cases = {
      // no END OF HEADER: the last line
      {"     3.05           OBSERVATION DATA    G: GPS              RINEX VERSION / TYPE\n"
       "G    2 C1C L1C                                              SYS / # / OBS TYPES\n",
       2, "END OF HEADER"},
      // fewer types listed than announced
      {"     3.05           OBSERVATION DATA    G: GPS              RINEX VERSION / TYPE\n"
       "G    3 C1C L1C                                              SYS / # / OBS TYPES\n"
       "                                                            END OF HEADER\n",
       2, "observation type 3 (columns 16-18)"},
      // file type not O
      {"     3.05           NAVIGATION DATA     G: GPS              RINEX VERSION / TYPE\n", 1, "column 21"},
      // the next epoch record where the third satellite should be
      {h + "> 2024 10 01 00 00  0.0000000  0  3\nG01  21234567.123   111586123.456\n"
           "G02  21234567.123   111586123.456\n> 2024 10 01 00 00  1.0000000  0  0\n",
       7, "truncated epoch"},
      // event record announcing 2 special records, 1 present
      {h + "> 2024 10 01 00 00  0.0000000  4  2\nA COMMENT                                                   COMMENT\n", 5,
       "truncated"},
      // no system letter
      {h + "> 2024 10 01 00 00  0.0000000  0  1\n 01  21234567.123   111586123.456\n", 5, "satellite system (column 1)"},
      // LLI not a digit
      {h + "> 2024 10 01 00 00  0.0000000  0  1\nG01  21234567.123x  111586123.456\n", 5, "C1C LLI (column 18)"},
      // signal strength not a digit
      {h + "> 2024 10 01 00 00  0.0000000  0  1\nG01  21234567.123   111586123.456 ?\n", 5,
       "L1C signal strength (column 35)"},
      // epoch flag 7
      {h + "> 2024 10 01 00 00  0.0000000  7  0\n", 4, "epoch flag (column 32)"},
      // malformed seconds
      {h + "> 2024 10 01 00 00  0.00x0000  0  0\n", 4, "second"},
      // missing satellite count
      {h + "> 2024 10 01 00 00  0.0000000  0\n", 4, "columns 33-35"},
      // non-numeric clock offset
      {h + "> 2024 10 01 00 00  0.0000000  0  0      -0.0000123x5678\n", 4, "receiver clock offset"},
      // a data line that is not an epoch record
      {h + "G01  21234567.123   111586123.456\n", 4, "'>'"},
      // PRN out of range
      {h + "> 2024 10 01 00 00  0.0000000  0  1\nG33  21234567.123   111586123.456\n", 5, "satellite number"},
  };
  for (const Malformed& c : cases) {
    test::TempFile file(c.text, ".rnx");
    const auto obs = read_rinex3_observations(file.path());
    ASSERT_FALSE(obs.ok()) << c.text;
    EXPECT_EQ(obs.error().field, file.path().string() + ":" + std::to_string(c.line)) << c.text;
    EXPECT_NE(obs.error().message.find(c.message_part), std::string::npos) << obs.error().message;
  }
}

TEST(RinexObs, MissingFileNamesThePath) {
  const auto obs = read_rinex3_observations("/nonexistent/visors.rnx");
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, "/nonexistent/visors.rnx");
}

}  // namespace
}  // namespace visors::gnss::files
