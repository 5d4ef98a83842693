// GRAPHIC and SDCP rows of the filter (nav/gps_measurement_model.hpp) against central differences
// of the whole prediction chain (state -> SI receiver estimate -> range model -> measurement) in
// every one of the 98 scaled states, and their values against the observation equations of
// docs/algorithms/gnss-measurements.md written out here.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "visors/gnss/gps_constants.hpp"
#include "visors/nav/gps_measurement_model.hpp"

namespace visors::nav {
namespace {

core::GpsTime epoch() { return core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value(); }

gnss::BroadcastEphemeris ephemeris() {
  gnss::BroadcastEphemeris e;
  e.prn = 12;
  e.toe = e.toc = e.transmission = epoch() - 900.0;
  e.af0_s = -1.3e-4;
  e.af1_sps = 2.2e-11;  // a large drift, so the SDCP's satellite-clock term is not negligible
  e.sqrt_a = 5153.7;
  e.eccentricity = 0.008;
  e.i0_rad = 0.96;
  e.omega0_rad = -0.4;
  e.omega_rad = 1.2;
  e.m0_rad = 0.3;
  e.crc_m = 150.0;
  return e;
}

constexpr int kB = state::kGraphicAmbiguities + 5;
constexpr int kN = state::kSdcpAmbiguities + 17;

// Both spacecraft 40 m apart in a LEO under the satellite, clocks 0.2 ms and -0.1 ms apart.
NavVector state_vector() {
  core::OnboardEarthFrame frame;
  const Eigen::Vector3d toward =
      (frame.gcrf_to_itrf_matrix(epoch()).transpose() * gnss::broadcast_state(ephemeris(), epoch()).r_ecef_m).normalized();
  const Eigen::Vector3d side = toward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d along = toward.cross(side);
  NavVector x = NavVector::Zero();
  for (Craft c : {Craft::kDsc, Craft::kOsc}) {
    const double offset = c == Craft::kOsc ? 40.0 : 0.0;
    x.segment<3>(state::position(c)) = 6878137.0 * (toward + 0.4 * side).normalized() + offset * along;
    x.segment<3>(state::velocity(c)) = 7.61e6 * (along + 0.3 * side).normalized();  // [mm/s]
    x.segment<3>(state::empirical_acceleration(c)) = Eigen::Vector3d(0.02, -0.01, 0.03);
    x.segment<3>(state::phase_center(c)) = Eigen::Vector3d(3.0, -2.0, 5.0);  // [mm]
  }
  x(state::clock(Craft::kDsc)) = 6.0e4;
  x(state::clock(Craft::kOsc)) = -3.0e4;
  x(kB) = 12.5;
  x(kN) = -7.3;
  return x;
}

AntennaGeometry antenna(Craft c) {
  AntennaGeometry a;
  a.body_to_gcrf = Eigen::AngleAxisd(c == Craft::kOsc ? 0.3 : 0.5, Eigen::Vector3d(1, -1, 2).normalized()).toRotationMatrix();
  a.arp_body_m = Eigen::Vector3d(0.1, 0.0, 0.15);
  a.pco_body_m = Eigen::Vector3d(0.0, 0.0, 0.0854);
  return a;
}

RangePrediction range(const NavVector& x, Craft c) {
  core::OnboardEarthFrame frame;
  return predict_range(epoch(), receiver_estimate(x, c), antenna(c), ephemeris(), frame);
}

MeasurementPrediction graphic(const NavVector& x) { return predict_graphic(x, Craft::kOsc, range(x, Craft::kOsc), kB); }
MeasurementPrediction sdcp(const NavVector& x) {
  return predict_sdcp(x, range(x, Craft::kOsc), range(x, Craft::kDsc), kN, gnss::kL1WavelengthM);
}

// Step per state, in its unit: 10 m, 1 km/s in mm/s, 1e5 m of clock, 1 m of phase centre in mm,
// 1 (B, N, empirical acceleration: these enter linearly or not at all).
double step(int i) {
  const int within = i < state::kGraphicAmbiguities ? i % kSpacecraftStates : -1;
  if (within >= 0 && within < 3) return 10.0;
  if (within >= 3 && within < 6) return 1e6;
  if (within == 9) return 1e5;
  if (within >= 10 && within < 13) return 1e3;
  return 1.0;
}

template <typename Measurement>
void expect_row_matches_central_differences(Measurement measure) {
  const NavVector x = state_vector();
  const NavRow h = measure(x).h;
  for (int i = 0; i < kNavStates; ++i) {
    NavVector plus = x, minus = x;
    plus(i) += step(i);
    minus(i) -= step(i);
    const double numeric = (measure(plus).value_m - measure(minus).value_m) / (2.0 * step(i));
    EXPECT_NEAR(h(i), numeric, 1e-7 * std::abs(numeric) + 1e-9) << "state " << i;
  }
}

TEST(GpsMeasurementModel, GraphicRowMatchesCentralDifferencesInEveryState) {
  expect_row_matches_central_differences(graphic);
}

TEST(GpsMeasurementModel, SdcpRowMatchesCentralDifferencesInEveryState) {
  expect_row_matches_central_differences(sdcp);
}

// GRAPHIC (docs/algorithms/gnss-measurements.md#graphic): G = rho + c dt_r - c dt^j + B.
TEST(GpsMeasurementModel, GraphicValueIsTheObservationEquation) {
  const NavVector x = state_vector();
  const RangePrediction r = range(x, Craft::kOsc);
  EXPECT_NEAR(graphic(x).value_m, r.range_m + x(state::clock(Craft::kOsc)) - r.satellite_clock_m + x(kB), 1e-6);
}

// SDCP (docs/algorithms/gnss-measurements.md#single-differences):
// dPhi = rho_d - rho_c + c dt_d - c dt_c + lambda N (+ the satellite clock's change
// between the two transmission instants, 0.3 ms apart here: 2.2e-11 x 3e-4 s x c = 2 um).
TEST(GpsMeasurementModel, SdcpValueIsTheObservationEquation) {
  const NavVector x = state_vector();
  const RangePrediction o = range(x, Craft::kOsc);
  const RangePrediction d = range(x, Craft::kDsc);
  const double expected = o.range_m - d.range_m + x(state::clock(Craft::kOsc)) - x(state::clock(Craft::kDsc)) +
                          gnss::kL1WavelengthM * x(kN) - (o.satellite_clock_m - d.satellite_clock_m);
  EXPECT_NEAR(sdcp(x).value_m, expected, 1e-6);
}

TEST(GpsMeasurementModel, SdcpKeepsTheSatelliteClockChangeBetweenTransmissions) {
  const NavVector x = state_vector();
  EXPECT_GT(std::abs(range(x, Craft::kOsc).satellite_clock_m - range(x, Craft::kDsc).satellite_clock_m), 1e-6);
}

TEST(GpsMeasurementModel, GraphicDoesNotSeeTheOtherSpacecraft) {
  const NavRow h = graphic(state_vector()).h;
  EXPECT_TRUE(h.segment<kSpacecraftStates>(state::block(Craft::kDsc)).isZero(0.0));
}

TEST(GpsMeasurementModel, SdcpAmbiguityEntersInWavelengths) {
  EXPECT_EQ(sdcp(state_vector()).h(kN), gnss::kL1WavelengthM);
}

}  // namespace
}  // namespace visors::nav
