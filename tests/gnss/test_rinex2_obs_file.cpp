// RINEX 2.10/2.11 observation files through read_rinex_observations: two real GEONET files (GSI
// stations 0759 and 3040, 2005-04-02, teqc output; data/SOURCES.md), hand-written files
// laid out after RINEX 2.11 (IGS/RTCM, 2012 update) Table A1 (header) and Table A2 (data records),
// malformed input (every error names "<path>:<line>" with the exact line), and the RINEX 2 to
// RINEX 3 GPS code mapping.
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "visors/gnss/files/rinex_obs_codes.hpp"
#include "visors/gnss/files/rinex_obs_file.hpp"
#include "gnss_test_data.hpp"
#include "support/temp_file.hpp"

namespace visors::gnss::files {
namespace {

core::GpsTime gps(const char* iso) { return core::GpsTime::parse(iso, core::TimeScale::kGps).value(); }

std::size_t satellite_records(const ObservationFile& f) {
  return std::accumulate(f.epochs.begin(), f.epochs.end(), std::size_t{0},
                         [](std::size_t n, const ObservationEpoch& e) { return n + e.satellites.size(); });
}

std::vector<int> prns(const ObservationEpoch& e) {
  std::vector<int> out;
  for (const auto& s : e.satellites) out.push_back(s.prn);
  return out;
}

// ---------------------------------------------------------------------------------------------
// Real files. Reference figures counted in the files with the shell, independently of the reader:
//   epochs: grep -cE '^ [0-9 ][0-9] [ 1][0-9] [ 0-3][0-9] [ 12][0-9] [ 0-5][0-9] [ 0-9][0-9]\.[0-9]{7}  [0-6]'
//           gives 120 epoch lines in each file, all with flag 0 (column 29), 00:00:00 to 00:59:30
//           every 30 s (the time tags drift by whole milliseconds, see below);
//   satellite records: the sum of columns 30-32 of those lines (awk) is 948 (0759) and 1039
//           (3040); with the 17 header lines and the teqc event records (flag 4, blank epoch, one
//           COMMENT "RINEX FILE SPLICE", 2 lines each: three in 0759, one in 3040) this makes
//           17 + 120 + 948 + 6 = 1091 and 17 + 120 + 1039 + 2 = 1178 lines, what wc -l reports.

TEST(Rinex2Obs, GsiStation0759Header) {
  VISORS_REQUIRE_GNSS_DATA(test::kGsi0759Obs);
  const auto obs = read_rinex_observations(test::gnss_data(test::kGsi0759Obs));
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  const ObservationHeader& h = obs->header;
  EXPECT_DOUBLE_EQ(obs->version, 2.10);  // line 1 "     2.10           OBSERVATION DATA    G (GPS)"
  EXPECT_EQ(h.observation_types, (std::vector<std::string>{"L1", "C1", "L2", "P2"}));  // line 12
  EXPECT_DOUBLE_EQ(h.interval_s, 30.0);                                                 // line 13 "30.0000"
  // line 9 "APPROX POSITION XYZ" (3F14.4), exactly as written
  EXPECT_DOUBLE_EQ(h.approx_position_m.x(), -3976219.5082);
  EXPECT_DOUBLE_EQ(h.approx_position_m.y(), 3382372.5671);
  EXPECT_DOUBLE_EQ(h.approx_position_m.z(), 3652512.9849);
  EXPECT_EQ(h.antenna_delta_hen_m, Eigen::Vector3d::Zero());  // line 10
  EXPECT_EQ(h.marker_name, "0759");                           // line 5
  EXPECT_EQ(h.receiver_type, "TRIMBLE 5700");                 // line 7
  EXPECT_EQ(h.receiver_version, "1.24");
  EXPECT_EQ(h.antenna_type, "TRM29659.00");  // line 8
  EXPECT_EQ(h.agency, "GEOGRAPHICAL SURVEY INSTITUTE, JAPAN");
  EXPECT_EQ(h.marker_type, "");  // no MARKER TYPE in RINEX 2: not the writer's default
  EXPECT_EQ(h.first_observation, gps("2005-04-02T00:00:00"));  // line 16, time system GPS
  EXPECT_EQ(h.wavelength_factors, (std::array<int, 2>{1, 1}));  // line 11
  EXPECT_TRUE(h.satellite_wavelength_factors.empty());
  EXPECT_EQ(h.comments.size(), 4u);  // lines 3, 4, 14, 15 (the event COMMENTs are not header)
}

TEST(Rinex2Obs, GsiStation0759Epochs) {
  VISORS_REQUIRE_GNSS_DATA(test::kGsi0759Obs);
  const auto obs = read_rinex_observations(test::gnss_data(test::kGsi0759Obs));
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  ASSERT_EQ(obs->epochs.size(), 120u);          // file comment: grep of the epoch lines
  EXPECT_EQ(satellite_records(*obs), 948u);      // file comment: sum of columns 30-32
  // Line 18: " 05  4  2  0  0  0.0000000  0  8G 3G 7G 8G11G19G20G24G28" (no clock offset).
  const ObservationEpoch& e = obs->epochs.front();
  EXPECT_EQ(e.t, gps("2005-04-02T00:00:00"));
  EXPECT_EQ(e.flag, 0);
  EXPECT_FALSE(e.receiver_clock_offset_s.has_value());
  EXPECT_EQ(prns(e), (std::vector<int>{3, 7, 8, 11, 19, 20, 24, 28}));
  // Line 19, G03: "  55923622.160    24767686.375    43647388.2424   24767684.8224", 63 columns
  // (the trailing blank removed). Counted: columns 1-14 "  55923622.160", 15-16 blank; 17-30
  // "  24767686.375", 31-32 blank; 33-46 "  43647388.242", column 47 (LLI) "4", column 48 (signal
  // strength) blank; 49-62 "  24767684.822", column 63 (LLI) "4", no signal strength. LLI 4 is
  // bit 2, "observation under anti-spoofing" (RINEX 2.11 section 7 and Table A2): the L2 and P2
  // of these semi-codeless receivers, not a signal strength.
  const SatelliteObservations& g03 = e.satellites.front();
  ASSERT_EQ(g03.values.size(), 4u);
  EXPECT_DOUBLE_EQ(*g03.values[0].value, 55923622.160);
  EXPECT_EQ(g03.values[0].lli, 0);
  EXPECT_EQ(g03.values[0].ssi, 0);
  EXPECT_DOUBLE_EQ(*g03.values[1].value, 24767686.375);
  EXPECT_DOUBLE_EQ(*g03.values[2].value, 43647388.242);
  EXPECT_EQ(g03.values[2].lli, 4);
  EXPECT_EQ(g03.values[2].ssi, 0);
  EXPECT_DOUBLE_EQ(*g03.values[3].value, 24767684.822);
  EXPECT_EQ(g03.values[3].lli, 4);
  EXPECT_EQ(g03.values[3].ssi, 0);
  // Line 857, after the event record of lines 855-856: " 05  4  2  0 48  0.0040000  0  8G 1G..."
  // is epoch 97 (00:48 is the 97th 30-s step from 00:00); the time tag keeps its 4 ms exactly.
  EXPECT_EQ(obs->epochs[96].t, gps("2005-04-02T00:48:00.004"));
  EXPECT_EQ(obs->epochs[96].satellites.front().prn, 1);
  // Line 1080, the last epoch: " 05  4  2  0 59 30.0050000  0  9G 1G 4G 7G11G19G20G23G24G28".
  EXPECT_EQ(obs->epochs.back().t, gps("2005-04-02T00:59:30.005"));
  EXPECT_EQ(prns(obs->epochs.back()), (std::vector<int>{1, 4, 7, 11, 19, 20, 23, 24, 28}));
}

// Whole-file counts over the 948 satellite records of 0759, counted with awk on the record lines
// (columns 1-14 L1, 33-46 L2 holding a digit; column 15 the L1 LLI, column 47 the L2 LLI): 944 L1
// and 924 L2 values, 10 L1 values with LLI 1 (loss of lock), 9 L2 values with LLI 5 (loss of
// lock + anti-spoofing).
TEST(Rinex2Obs, GsiStation0759Counts) {
  VISORS_REQUIRE_GNSS_DATA(test::kGsi0759Obs);
  const auto obs = read_rinex_observations(test::gnss_data(test::kGsi0759Obs));
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  std::size_t l1 = 0, l2 = 0, l1_slips = 0, l2_slips = 0;
  for (const auto& e : obs->epochs) {
    for (const auto& s : e.satellites) {
      l1 += s.values[0].value.has_value() ? 1 : 0;
      l2 += s.values[2].value.has_value() ? 1 : 0;
      l1_slips += s.values[0].lli == 1 ? 1 : 0;
      l2_slips += s.values[2].lli == 5 ? 1 : 0;
    }
  }
  EXPECT_EQ(l1, 944u);
  EXPECT_EQ(l2, 924u);
  EXPECT_EQ(l1_slips, 10u);
  EXPECT_EQ(l2_slips, 9u);
}

TEST(Rinex2Obs, GsiStation3040) {
  VISORS_REQUIRE_GNSS_DATA(test::kGsi3040Obs);
  const auto obs = read_rinex_observations(test::gnss_data(test::kGsi3040Obs));
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  // line 9 "APPROX POSITION XYZ"
  EXPECT_DOUBLE_EQ(obs->header.approx_position_m.x(), -3978242.4348);
  EXPECT_EQ(obs->header.marker_name, "3040");
  ASSERT_EQ(obs->epochs.size(), 120u);       // file comment: grep of the epoch lines
  EXPECT_EQ(satellite_records(*obs), 1039u);  // file comment: sum of columns 30-32
  // Line 18: " 05  4  2  0  0  0.0000000  0  9G 3G 7G 8G11G19G20G24G27G28"; line 19, G03:
  // " -41706426.668    24801780.917   -32471209.7934   24801779.3144" (negative phases).
  const ObservationEpoch& e = obs->epochs.front();
  EXPECT_EQ(prns(e), (std::vector<int>{3, 7, 8, 11, 19, 20, 24, 27, 28}));
  EXPECT_DOUBLE_EQ(*e.satellites[0].values[0].value, -41706426.668);
  EXPECT_DOUBLE_EQ(*e.satellites[0].values[2].value, -32471209.793);
  EXPECT_EQ(e.satellites[0].values[2].lli, 4);  // column 47: anti-spoofing (see the 0759 test)
  // Line 138: " 05  4  2  0  5 59.9990000": the receiver's tag 1 ms before the 00:06 grid point.
  EXPECT_EQ(obs->epochs[12].t, gps("2005-04-02T00:05:59.999"));
  EXPECT_EQ(obs->epochs.back().t, gps("2005-04-02T00:59:29.996"));  // line 1167
}

// ---------------------------------------------------------------------------------------------
// Hand-written files (Tables A1/A2; columns checked by counting).

// Mixed file: 10 types (a "# / TYPES OF OBSERV" continuation line, two record lines per
// satellite), 14 satellites (a continuation line of the satellite list, columns 33-38), one of them
// GLONASS (skipped, its lines consumed), a receiver clock offset (F12.9, columns 69-80), LLI and
// signal strength digits, blank values and a 0.000 value (absent, Table A2), default and
// satellite-specific wavelength factors, an event (flag 4, blank epoch, 2 special records), a
// blank satellite system letter (GPS), and two-digit years 99 (1999) and 00 (2000).
const char* const kMixedFile =
    "     2.11           OBSERVATION DATA    M (MIXED)           RINEX VERSION / TYPE\n"
    "hand-written        VISORS              20240101 000000 UTC PGM / RUN BY / DATE\n"
    "SYN1                                                        MARKER NAME\n"
    "    10    C1    L1    L2    P2    D1    S1    P1    D2    S2# / TYPES OF OBSERV\n"
    "          C2                                                # / TYPES OF OBSERV\n"
    "     1     1                                                WAVELENGTH FACT L1/2\n"
    "     1     2     2   G05   G12                              WAVELENGTH FACT L1/2\n"
    "     1.000                                                  INTERVAL\n"
    "  1999    12    31    23    59   58.0000000     GPS         TIME OF FIRST OBS\n"
    "                                                            END OF HEADER\n"
    " 99 12 31 23 59 58.0000000  0 14G01G02G03G04G05G06R05G07G08G09G10G11-0.123456789\n"
    "                                G12G13\n"
    "  20000001.000   105000001.25017                  20000003.500       -1234.567\n"
    "        45.000           0.000                                    20000002.125\n"
    "  20002000.125\n"
    "                                                                  20002000.500 6\n"
    "  20003000.125\n"
    "                                                                  20003000.500 6\n"
    "  20004000.125\n"
    "                                                                  20004000.500 6\n"
    "  20005000.125\n"
    "                                                                  20005000.500 6\n"
    "  20006000.125\n"
    "                                                                  20006000.500 6\n"
    "  19000005.000   101000005.000\n"
    "\n"
    "  20007000.125\n"
    "                                                                  20007000.500 6\n"
    "  20008000.125\n"
    "                                                                  20008000.500 6\n"
    "  20009000.125\n"
    "                                                                  20009000.500 6\n"
    "  20010000.125\n"
    "                                                                  20010000.500 6\n"
    "  20011000.125\n"
    "                                                                  20011000.500 6\n"
    "  20012000.125\n"
    "                                                                  20012000.500 6\n"
    "  20013000.125\n"
    "                                                                  20013000.500 6\n"
    "                            4  2\n"
    "an event inside the data                                    COMMENT\n"
    "a second special record                                     COMMENT\n"
    " 99 12 31 23 59 59.0000000  0  1 5\n"
    "  20005000.250   105005000.5005\n"
    "\n"
    " 00  1  1  0  0  0.0000000  0  1G05\n"
    "  20005100.250\n"
    "\n";

TEST(Rinex2Obs, HandWrittenMixedFileHeader) {
  test::TempFile file(kMixedFile, ".99o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  const ObservationHeader& h = obs->header;
  EXPECT_DOUBLE_EQ(obs->version, 2.11);
  EXPECT_EQ(h.observation_types,
            (std::vector<std::string>{"C1", "L1", "L2", "P2", "D1", "S1", "P1", "D2", "S2", "C2"}));
  EXPECT_EQ(h.program, "hand-written");
  EXPECT_EQ(h.creation_date, "20240101 000000 UTC");
  EXPECT_EQ(h.marker_name, "SYN1");
  EXPECT_DOUBLE_EQ(h.interval_s, 1.0);
  EXPECT_EQ(h.first_observation, gps("1999-12-31T23:59:58"));
  EXPECT_EQ(h.wavelength_factors, (std::array<int, 2>{1, 1}));
  ASSERT_EQ(h.satellite_wavelength_factors.size(), 2u);
  EXPECT_EQ(h.satellite_wavelength_factors.at(5), (std::array<int, 2>{1, 2}));
  EXPECT_EQ(h.satellite_wavelength_factors.at(12), (std::array<int, 2>{1, 2}));
}

TEST(Rinex2Obs, HandWrittenMixedFileEpochs) {
  test::TempFile file(kMixedFile, ".99o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  ASSERT_EQ(obs->epochs.size(), 3u);  // the event record is not an epoch
  const ObservationEpoch& e0 = obs->epochs[0];
  EXPECT_EQ(e0.t, gps("1999-12-31T23:59:58"));
  EXPECT_DOUBLE_EQ(*e0.receiver_clock_offset_s, -0.123456789);
  EXPECT_EQ(prns(e0), (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}));  // R05 skipped
  const SatelliteObservations& g01 = e0.satellites[0];
  ASSERT_EQ(g01.values.size(), 10u);
  EXPECT_DOUBLE_EQ(*g01.values[0].value, 20000001.0);      // C1
  EXPECT_DOUBLE_EQ(*g01.values[1].value, 105000001.25);    // L1 "105000001.25017"
  EXPECT_EQ(g01.values[1].lli, 1);
  EXPECT_EQ(g01.values[1].ssi, 7);
  EXPECT_FALSE(g01.values[2].value.has_value());           // L2 blank
  EXPECT_DOUBLE_EQ(*g01.values[4].value, -1234.567);       // D1
  EXPECT_DOUBLE_EQ(*g01.values[5].value, 45.0);            // S1, second record line
  EXPECT_FALSE(g01.values[6].value.has_value());           // P1 written as 0.000
  EXPECT_FALSE(g01.values[8].value.has_value());           // S2 blank
  EXPECT_DOUBLE_EQ(*g01.values[9].value, 20000002.125);    // C2
  // G07, after the GLONASS record, and G13, listed on the continuation line.
  EXPECT_DOUBLE_EQ(*e0.satellites[6].values[0].value, 20007000.125);
  EXPECT_DOUBLE_EQ(*e0.satellites[12].values[0].value, 20013000.125);
  EXPECT_DOUBLE_EQ(*e0.satellites[12].values[9].value, 20013000.5);
  EXPECT_EQ(e0.satellites[12].values[9].ssi, 6);
  EXPECT_FALSE(e0.satellites[12].values[1].value.has_value());  // a line ending after the first value
  const ObservationEpoch& e1 = obs->epochs[1];
  EXPECT_EQ(e1.t, gps("1999-12-31T23:59:59"));
  EXPECT_FALSE(e1.receiver_clock_offset_s.has_value());
  EXPECT_EQ(prns(e1), (std::vector<int>{5}));  // " 5": blank system letter
  EXPECT_EQ(e1.satellites[0].values[1].lli, 5);  // lost lock + anti-spoofing
  EXPECT_EQ(obs->epochs[2].t, gps("2000-01-01T00:00:00"));  // year 00
}

// GPS-only file with 5 types (one record line per satellite), exactly 12 satellites (no
// continuation line), a power-failure epoch (flag 1, kept), cycle-slip records (flag 6, dropped),
// events 2, 3 (with header records), 4 (repeating the same types) and 5, an empty epoch.
const char* const kEventsFile =
    "     2.10           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n"
    "     5    C1    L1    L2    P2    S1                        # / TYPES OF OBSERV\n"
    "                                                            END OF HEADER\n"
    " 24 10  1  0  0  0.0000000  0 12G02G04G06G08G10G12G14G16G18G20G22G24\n"
    "  21000002.000   110000002.000    86000002.000    21000005.000          40.500\n"
    "  21000004.000   110000004.000    86000004.000    21000007.000          41.000\n"
    "  21000006.000   110000006.000    86000006.000    21000009.000          41.500\n"
    "  21000008.000   110000008.000    86000008.000    21000011.000          42.000\n"
    "  21000010.000   110000010.000    86000010.000    21000013.000          42.500\n"
    "  21000012.000   110000012.000    86000012.000    21000015.000          43.000\n"
    "  21000014.000   110000014.000    86000014.000    21000017.000          43.500\n"
    "  21000016.000   110000016.000    86000016.000    21000019.000          44.000\n"
    "  21000018.000   110000018.000    86000018.000    21000021.000          44.500\n"
    "  21000020.000   110000020.000    86000020.000    21000023.000          45.000\n"
    "  21000022.000   110000022.000    86000022.000    21000025.000          45.500\n"
    "  21000024.000   110000024.000    86000024.000    21000027.000          46.000\n"
    " 24 10  1  0  0  1.0000000  1  1G02\n"
    "  21000100.000   110000500.00018\n"
    " 24 10  1  0  0  1.0000000  6  1G02\n"
    "                         3.000\n"
    " 24 10  1  0  0  1.5000000  2  0\n"
    "                            3  2\n"
    "NEWSITE                                                     MARKER NAME\n"
    " -3976219.5082  3382372.5671  3652512.9849                  APPROX POSITION XYZ\n"
    "                            4  1\n"
    "     5    C1    L1    L2    P2    S1                        # / TYPES OF OBSERV\n"
    " 24 10  1  0  0  1.7500000  5  0\n"
    " 24 10  1  0  0  2.0000000  0  0\n"
    " 24 10  1  0  0  3.0000000  0  1G04\n"
    "  21000200.000\n";

TEST(Rinex2Obs, EventAndCycleSlipRecordsAreReadPast) {
  test::TempFile file(kEventsFile, ".24o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  ASSERT_EQ(obs->epochs.size(), 4u);  // flags 0, 1, then the empty epoch and the last one
  EXPECT_EQ(obs->epochs[0].satellites.size(), 12u);
  EXPECT_EQ(obs->epochs[0].satellites.back().prn, 24);
  EXPECT_DOUBLE_EQ(*obs->epochs[0].satellites.back().values[4].value, 46.0);
  EXPECT_EQ(obs->epochs[1].flag, 1);
  EXPECT_EQ(obs->epochs[1].satellites[0].values[1].lli, 1);
  EXPECT_EQ(obs->epochs[1].satellites[0].values[1].ssi, 8);
  EXPECT_EQ(obs->epochs[2].t, gps("2024-10-01T00:00:02"));
  EXPECT_TRUE(obs->epochs[2].satellites.empty());
  EXPECT_EQ(obs->epochs[3].t, gps("2024-10-01T00:00:03"));
  EXPECT_EQ(prns(obs->epochs[3]), (std::vector<int>{4}));
  EXPECT_EQ(obs->header.marker_name, "");  // the flag-3 MARKER NAME is not applied
}

// The dispatching reader reads RINEX 3 files like read_rinex3_observations.
TEST(Rinex2Obs, DispatchReadsRinex3Too) {
  ObservationFile f;
  f.header.first_observation = gps("2024-10-01T00:00:00");
  f.epochs.push_back({gps("2024-10-01T00:00:00"), 0, {}, {{7, {{2.1e7, 0, 7}, {1.1e8, 1, 7}, {-1.5e3, 0, 0}, {45.0, 0, 0}}}}});
  test::TempFile file("", ".rnx");
  ASSERT_TRUE(write_rinex3_observations(file.path(), f).ok());
  const auto obs = read_rinex_observations(file.path());
  ASSERT_TRUE(obs.ok()) << obs.error().describe();
  EXPECT_DOUBLE_EQ(obs->version, 3.05);
  EXPECT_EQ(obs->header.observation_types, f.header.observation_types);
  ASSERT_EQ(obs->epochs.size(), 1u);
  EXPECT_EQ(obs->epochs[0].satellites[0].values[1].lli, 1);
}

// ---------------------------------------------------------------------------------------------
// Malformed input: each error names the file and the exact line, and the problem.

struct Malformed {
  const char* what;
  std::string text;
  int line;
  std::string message_part;
};

const std::string kHeader2 =
    "     2.11           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n"
    "     2    C1    L1                                          # / TYPES OF OBSERV\n"
    "                                                            END OF HEADER\n";
const std::string kEpoch2 = " 05  4  2  0  0  0.0000000  0  2G01G02\n";  // line 4

void expect_malformed(const Malformed& c) {
  test::TempFile file(c.text, ".05o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_FALSE(obs.ok()) << c.what;
  EXPECT_EQ(obs.error().field, file.path().string() + ":" + std::to_string(c.line)) << c.what;
  EXPECT_NE(obs.error().message.find(c.message_part), std::string::npos) << c.what << ": " << obs.error().message;
}

TEST(Rinex2Obs, MalformedHeaderNamesFileAndLine) {
  const std::string v = "     2.11           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n";
  const std::vector<Malformed> cases = {
      {"no END OF HEADER: the last line", v + "     2    C1    L1                                          # / TYPES OF OBSERV\n",
       2, "END OF HEADER"},
      {"no types", v + "                                                            END OF HEADER\n", 2,
       "no # / TYPES OF OBSERV"},
      {"a type missing on its line",
       v + "     3    C1    L1                                          # / TYPES OF OBSERV\n", 2,
       "observation type 3 (columns 23-24) is missing"},
      {"10 types announced, 9 listed",
       v + "    10    C1    L1    L2    P2    D1    S1    P1    D2    S2# / TYPES OF OBSERV\n"
           "                                                            END OF HEADER\n",
       3, "announces 10 types, 9 are listed"},
      {"not a code", v + "     2    C1    l1                                          # / TYPES OF OBSERV\n", 2,
       "'l1' is not a RINEX 2 code"},
      {"version 1", "     1.00           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n", 1,
       "is not 2.x or 3.x"},
      {"version 4", "     4.00           OBSERVATION DATA    G (GPS)             RINEX VERSION / TYPE\n", 1,
       "is not 2.x or 3.x"},
      {"navigation file", "     2.11           NAVIGATION DATA                         RINEX VERSION / TYPE\n", 1,
       "file type (column 21)"},
      {"GLONASS-only file", "     2.11           OBSERVATION DATA    R (GLONASS)         RINEX VERSION / TYPE\n", 1,
       "satellite system (column 41) 'R'"},
      {"GLONASS time system", v + "  2005     4     2     0     0    0.0000000     GLO         TIME OF FIRST OBS\n", 2,
       "only GPS"},
      {"wavelength factor 3", v + "     3     1                                                WAVELENGTH FACT L1/2\n", 2,
       "L1 wavelength factor (columns 1-6) must be 1 or 2"},
      {"wavelength satellite PRN 33",
       v + "     2     2     1   G33                                    WAVELENGTH FACT L1/2\n", 2,
       "wavelength factor satellite 1 (columns 22-24)"},
      {"position not a number", v + " -3976219.5O82  3382372.5671  3652512.9849                  APPROX POSITION XYZ\n",
       2, "APPROX POSITION XYZ"},
  };
  for (const Malformed& c : cases) expect_malformed(c);
}

TEST(Rinex2Obs, MalformedDataNamesFileAndLine) {
  const std::string h = kHeader2, e = kEpoch2;
  const std::string g1 = "  20000001.000   105000001.250\n", g2 = "  20000002.000   105000002.250\n";
  const std::vector<Malformed> cases = {
      {"file ends in the records", h + e + g1, 5, "the file ends in the records of satellite 2 (G02): truncated"},
      {"the next epoch where a record should be", h + e + g1 + " 05  4  2  0  0 30.0000000  0  1G01\n" + g1, 6,
       "an epoch record starts in the records of satellite 2"},
      {"an event line where a record should be", h + e + g1 + "                            4  1\n", 6,
       "an epoch record starts"},
      {"letters in a value", h + e + g1 + "  2000000x.000   105000002.250\n", 6, "G02 C1 (columns 1-14): '2000000x.000'"},
      {"letters in the second value", h + e + "  20000001.000   105000O01.250\n" + g2, 5, "G01 L1 (columns 17-30)"},
      {"LLI not a digit", h + e + "  20000001.000x  105000001.250\n" + g2, 5, "C1 LLI (column 15)"},
      {"signal strength not a digit", h + e + "  20000001.000 ? 105000001.250\n" + g2, 5,
       "C1 signal strength (column 16)"},
      {"month 13", h + " 05 13  2  0  0  0.0000000  0  1G01\n" + g1, 4, "epoch record"},
      {"month not a number", h + " 05 x4  2  0  0  0.0000000  0  1G01\n" + g1, 4, "month (columns 5-6)"},
      {"seconds not a number", h + " 05  4  2  0  0  0.00x0000  0  1G01\n" + g1, 4, "second (columns 16-26)"},
      {"epoch flag 7", h + " 05  4  2  0  0  0.0000000  7  1G01\n" + g1, 4, "epoch flag 0-6 in column 29"},
      {"a record where an epoch line should be", h + g1, 4, "expected an epoch record"},
      {"no satellite count", h + " 05  4  2  0  0  0.0000000  0\n", 4, "(columns 30-32) is missing"},
      {"satellite count not a number", h + " 05  4  2  0  0  0.0000000  0 x2G01G02\n" + g1 + g2, 4,
       "number of satellites (columns 30-32)"},
      {"system letter X", h + " 05  4  2  0  0  0.0000000  0  2G01X02\n" + g1 + g2, 4,
       "satellite 2 (columns 36-38): 'X' is not a satellite system"},
      {"GPS PRN 33", h + " 05  4  2  0  0  0.0000000  0  1G33\n" + g1, 4, "satellite 1 (columns 33-35): G33"},
      {"satellite number missing", h + " 05  4  2  0  0  0.0000000  0  2G01G\n" + g1 + g2, 4,
       "satellite 2 (columns 36-38) is missing"},
      {"clock offset not a number", h + " 05  4  2  0  0  0.0000000  0  1G01" + std::string(33, ' ') + "-0.12345x789\n" + g1,
       4, "receiver clock offset (columns 69-80)"},
      {"satellite list continuation missing",
       h + " 05  4  2  0  0  0.0000000  0 13G01G02G03G04G05G06G07G08G09G10G11G12\n", 4, "truncated satellite list"},
      {"satellite list continuation not blank in columns 1-32",
       h + " 05  4  2  0  0  0.0000000  0 13G01G02G03G04G05G06G07G08G09G10G11G12\n" + g1, 5,
       "a continuation line must have columns 1-32 blank"},
      {"event record truncated", h + "                            4  2\nA COMMENT" + std::string(51, ' ') + "COMMENT\n", 5,
       "the event record of line 4 announces 2 special records, the file ends after 1"},
      {"event changes the types",
       h + "                            4  1\n     2    C1    L2                                          # / TYPES OF OBSERV\n",
       5, "changes the observation types"},
  };
  for (const Malformed& c : cases) expect_malformed(c);
}

TEST(Rinex2Obs, EmptyAndMissingFilesNameThePath) {
  test::TempFile empty("", ".05o");
  const auto a = read_rinex_observations(empty.path());
  ASSERT_FALSE(a.ok());
  EXPECT_EQ(a.error().field, empty.path().string());
  const auto b = read_rinex_observations("/nonexistent/visors.05o");
  ASSERT_FALSE(b.ok());
  EXPECT_EQ(b.error().field, "/nonexistent/visors.05o");
}

// Malformed copies of the real file: the error names the line of the real file.
using Rinex2ObsGsiMalformed = test::MalformedCopy<test::kGsi0759Obs>;

TEST_F(Rinex2ObsGsiMalformed, TruncatedInsideTheSecondEpoch) {
  // Line 27 starts the second epoch (8 satellites, lines 28-35); cut after line 30.
  test::TempFile file(test::first_lines(text_, 30), ".05o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":30");
  EXPECT_NE(obs.error().message.find("satellite 4 (G11)"), std::string::npos) << obs.error().message;
}

TEST_F(Rinex2ObsGsiMalformed, LettersInTheFirstValue) {
  test::TempFile file(with_line(19, "  55923622.1x0    24767686.375    43647388.2424   24767684.8224"), ".05o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":19");
  EXPECT_NE(obs.error().message.find("G03 L1 (columns 1-14)"), std::string::npos) << obs.error().message;
}

TEST_F(Rinex2ObsGsiMalformed, NoEndOfHeader) {
  test::TempFile file(with_line(17, ""), ".05o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":1091");  // the last line (wc -l)
  EXPECT_NE(obs.error().message.find("END OF HEADER"), std::string::npos) << obs.error().message;
}

TEST_F(Rinex2ObsGsiMalformed, EpochLineWithoutItsFlag) {
  test::TempFile file(with_line(27, " 05  4  2  0  0 30.0000000     8G 3G 7G 8G11G19G20G24G28"), ".05o");
  const auto obs = read_rinex_observations(file.path());
  ASSERT_FALSE(obs.ok());
  EXPECT_EQ(obs.error().field, file.path().string() + ":27");
  EXPECT_NE(obs.error().message.find("column 29"), std::string::npos) << obs.error().message;
}

// ---------------------------------------------------------------------------------------------
// RINEX 2 -> RINEX 3 GPS codes (rinex_obs_codes.hpp: RINEX 2.11 Table A1 / section 10.1.1 codes,
// RINEX 3.05 section 5.1 attributes C, W, X).

TEST(Rinex2Codes, GpsCodes) {
  const std::vector<std::pair<const char*, const char*>> table = {
      {"C1", "C1C"}, {"P1", "C1W"}, {"L1", "L1C"}, {"D1", "D1C"}, {"S1", "S1C"}, {"C2", "C2X"}, {"P2", "C2W"},
      {"L2", "L2W"}, {"D2", "D2W"}, {"S2", "S2W"}, {"C5", "C5X"}, {"L5", "L5X"}, {"D5", "D5X"}, {"S5", "S5X"}};
  for (const auto& [rinex2, rinex3] : table) {
    const auto code = rinex2_gps_observation_code(rinex2);
    ASSERT_TRUE(code.has_value()) << rinex2;
    EXPECT_EQ(*code, rinex3) << rinex2;
  }
}

TEST(Rinex2Codes, NotGpsObservables) {
  for (const char* code : {"L7", "C6", "L8", "T1", "P5", "l1", "C", "C1C", "", "X1"}) {
    EXPECT_FALSE(rinex2_gps_observation_code(code).has_value()) << code;
  }
}

}  // namespace
}  // namespace visors::gnss::files
