// Acceptance of the broadcast orbits: broadcast ephemerides against the IGS final orbits of the
// same day, over all healthy satellites and all SP3 epochs (15 min). Broadcast orbits refer to the
// antenna phase centre as the control segment defines it, SP3 to the centre of mass: the comparison
// is made without any correction, so the offset (mostly along the nadir, 0 to 1.6 m depending on
// the satellite block) is part of the error, the conservative choice. The per-satellite mean radial
// difference is reported as the estimate of that offset, and the RMS after removing it.
#include <cmath>
#include <cstdio>
#include <map>

#include <gtest/gtest.h>

#include "visors/gnss/ephemeris_set.hpp"
#include "visors/gnss/files/rinex_nav_file.hpp"
#include "visors/gnss/files/sp3_file.hpp"
#include "gnss_test_data.hpp"

namespace visors::gnss {
namespace {

struct Comparison {
  double rms_3d_m = 0.0;
  double worst_satellite_rms_m = 0.0;
  int worst_prn = 0;
  double rms_without_radial_offset_m = 0.0;
  int samples = 0;
  int satellites = 0;
};

Comparison compare(const char* nav_name, const char* sp3_name) {
  const auto nav = files::read_rinex_navigation(test::gnss_data(nav_name));
  EXPECT_TRUE(nav.ok()) << nav.error().describe();
  const auto sp3 = files::Sp3Orbit::read(test::gnss_data(sp3_name));
  EXPECT_TRUE(sp3.ok()) << sp3.error().describe();
  const auto set = EphemerisSet::screen(nav->records, nav->record_lines);
  struct Sums {
    double square = 0.0, radial = 0.0, radial_square = 0.0;
    int n = 0;
  };
  std::map<int, Sums> by_prn;
  for (std::size_t k = 0; k < sp3->epochs().size(); ++k) {
    const core::GpsTime t = sp3->epochs()[k];
    for (int prn = 1; prn <= kMaxGpsPrn; ++prn) {
      const auto precise = sp3->position_m(prn, k);
      const BroadcastEphemeris* eph = set.select(prn, t);
      if (!precise || eph == nullptr) continue;
      const Eigen::Vector3d d = broadcast_state(*eph, t).r_ecef_m - *precise;
      const double radial = d.dot(precise->normalized());
      Sums& s = by_prn[prn];
      s.square += d.squaredNorm();
      s.radial += radial;
      s.radial_square += radial * radial;
      ++s.n;
    }
  }
  Comparison c;
  double square = 0.0, square_without = 0.0;
  for (const auto& [prn, s] : by_prn) {
    const double rms = std::sqrt(s.square / s.n);
    const double mean_radial = s.radial / s.n;
    // Removing the mean radial offset: sum (d - m r_hat)^2 = sum d^2 - 2 m sum radial + n m^2.
    square_without += s.square - s.n * mean_radial * mean_radial;
    square += s.square;
    c.samples += s.n;
    ++c.satellites;
    if (rms > c.worst_satellite_rms_m) {
      c.worst_satellite_rms_m = rms;
      c.worst_prn = prn;
    }
    std::printf("G%02d  %3d epochs  RMS %.2f m  mean radial %+.2f m\n", prn, s.n, rms, mean_radial);
  }
  c.rms_3d_m = std::sqrt(square / c.samples);
  c.rms_without_radial_offset_m = std::sqrt(square_without / c.samples);
  std::printf("%s: %d satellites, %d samples, 3D RMS %.3f m (%.3f m without each satellite's mean radial offset), worst G%02d %.2f m\n",
              nav_name, c.satellites, c.samples, c.rms_3d_m, c.rms_without_radial_offset_m, c.worst_prn,
              c.worst_satellite_rms_m);
  return c;
}

// 2010-07-01: measured 3D RMS 1.866 m over 30 satellites (G01 and G25 unhealthy all day; the
// corrupt G01 record screened out) and 2,880 samples; worst satellite G09 3.15 m; 1.585 m without
// the per-satellite mean radial offsets (-1.6 to +0.2 m). The same numbers came out of an
// independent Python evaluation of Table 20-IV on the same files.
TEST(BroadcastVsPrecise, IgsDay20100701) {
  VISORS_REQUIRE_GNSS_DATA(test::kSp320100701);
  const Comparison c = compare(test::kBrdc20100701, test::kSp320100701);
  EXPECT_EQ(c.satellites, 30);
  EXPECT_EQ(c.samples, 2880);
  EXPECT_LT(c.rms_3d_m, 2.5);               // acceptance bound: 3D RMS below 2.5 m
  EXPECT_LT(c.worst_satellite_rms_m, 4.0);  // acceptance bound: every satellite below 4 m RMS
  // removing the mean radial offset can only lower the RMS (identity above); measured 1.585 m < 1.866 m (2026-11)
  EXPECT_LT(c.rms_without_radial_offset_m, c.rms_3d_m);
}

// The next day, a second independent data set: measured 1.803 m 3D RMS (1.506 m without the radial
// offsets), 30 satellites, worst G09 3.04 m.
TEST(BroadcastVsPrecise, IgsDay20100702) {
  VISORS_REQUIRE_GNSS_DATA(test::kSp320100702);
  const Comparison c = compare(test::kBrdc20100702, test::kSp320100702);
  EXPECT_GE(c.satellites, 29);
  EXPECT_LT(c.rms_3d_m, 2.5);
  EXPECT_LT(c.worst_satellite_rms_m, 4.0);
}

}  // namespace
}  // namespace visors::gnss
