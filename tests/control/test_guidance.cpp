// Guidance: standby orbit, the aligned science orbit (checked in exact inertial geometry, not
// through the linear map it was built with), and the passively safe transfer waypoints.

#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "visors/astro/keplerian_elements.hpp"
#include "visors/astro/relative_orbital_elements.hpp"
#include "visors/astro/roe_rtn_map.hpp"
#include "visors/astro/roe_stm.hpp"
#include "visors/astro/apparent_sun.hpp"
#include "visors/astro/j2_secular.hpp"
#include "visors/control/guidance.hpp"
#include "visors/core/constants.hpp"
#include "visors/core/rtn_frame.hpp"

namespace visors::control {
namespace {

namespace roe = astro::roe;

// Mission chief (mean): a = R_E + 500 km, e = 0.004, i = 97.8 deg, RAAN 157.5 deg (LTAN 10:00 on
// 2024-10-01), argp 90 deg.
const astro::KeplerianElements kChief{6878136.3, 0.004, 97.8 * core::kDegToRad, 157.5 * core::kDegToRad,
                                      90.0 * core::kDegToRad, 0.0};
const core::GpsTime kEpoch = core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kUtc).value();
constexpr double kMu = 3.986004415e14;

TEST(Guidance, StandbyIsTheTwoHundredMetreEiSeparation) {
  const astro::RelativeOrbitalElements s = kChief.a * standby_roe(kChief.a);
  // Guffanti et al., AAS 23-149, 2023, Table 5: a*[0, 0, 0, 200, 0, 200] m.
  EXPECT_NEAR(s[roe::kDey], 200.0, 1e-9);
  EXPECT_NEAR(s[roe::kDiy], 200.0, 1e-9);
  EXPECT_NEAR(s[roe::kDex], 0.0, 1e-9);
  EXPECT_NEAR(s[roe::kDix], 0.0, 1e-9);
}

// The exact relative state of the science ROE at the observation time: deputy elements from the
// ROE (nonlinear, astro::deputy_from_roe), both to Cartesian, differenced inertially. The
// guidance built the ROE with the first-order eccentric map; this measures what is left.
struct ExactRelative {
  Eigen::Vector3d r_gcrf;
  Eigen::Vector3d v_gcrf;
  Eigen::Vector3d sun;
};

// The line of sight: the target's apparent direction from the chief (astro/apparent_sun.hpp,
// verified on its own against ERFA and published apparent places).
ExactRelative exact_relative(const ScienceOrbit& orbit, const Eigen::Vector2d& target_offset_rad = Eigen::Vector2d::Zero()) {
  const astro::KeplerianElements chief = astro::propagate_mean_j2(kChief, orbit.t_obs);
  const astro::KeplerianElements deputy = astro::deputy_from_roe(chief, orbit.roe).value();
  const core::StateVector c = astro::cartesian_from_keplerian(chief, kMu);
  const core::StateVector d = astro::cartesian_from_keplerian(deputy, kMu);
  return {d.r - c.r, d.v - c.v, astro::apparent_target_unit_gcrf(kEpoch + orbit.t_obs, c, target_offset_rad)};
}

// Mission requirements (Guffanti et al., AAS 23-149, 2023, sec. 2, science requirements): 40 m
// +/- 15 mm along the Sun line, lateral offset <= 18 mm, lateral inertial velocity <= 0.2 mm/s.
// A target 310" east and 240" south of the disc centre (392": 76 mm at 40 m, four times the
// lateral requirement): the science orbit aims at it, not at the Sun's centre.
TEST(Guidance, ScienceOrbitAimsAtTheCommandedTarget) {
  ScienceGeometry geometry;
  geometry.target_offset_rad = Eigen::Vector2d(310.0, -240.0) * core::kArcsecToRad;
  const auto orbit = science_orbit(kChief, kEpoch, geometry);
  ASSERT_TRUE(orbit.ok()) << orbit.error().describe();
  const ExactRelative x = exact_relative(orbit.value(), geometry.target_offset_rad);
  EXPECT_LT((x.r_gcrf - x.r_gcrf.dot(x.sun) * x.sun).norm(), 0.018);
}

TEST(Guidance, ScienceOrbitRefusesANonFiniteTarget) {
  ScienceGeometry geometry;
  geometry.target_offset_rad.x() = std::nan("");
  EXPECT_EQ(science_orbit(kChief, kEpoch, geometry).error().field, "target_offset_rad");
}

TEST(Guidance, ScienceOrbitPutsTheOpticsSpacecraftFortyMetresSunward) {
  const auto orbit = science_orbit(kChief, kEpoch);
  ASSERT_TRUE(orbit.ok()) << orbit.error().describe();
  const ExactRelative x = exact_relative(orbit.value());
  const double along = x.r_gcrf.dot(x.sun);
  const double lateral = (x.r_gcrf - along * x.sun).norm();
  const double lateral_velocity = (x.v_gcrf - x.v_gcrf.dot(x.sun) * x.sun).norm();
  std::printf("science orbit at t_obs = %.1f s (u = %.2f deg, beta = %.2f deg): along %.4f m, lateral %.2f mm, "
              "lateral velocity %.4f mm/s\n",
              orbit->t_obs, orbit->u_obs / core::kDegToRad, orbit->beta / core::kDegToRad, along, 1e3 * lateral,
              1e3 * lateral_velocity);
  EXPECT_NEAR(along, 40.0, 0.015);
  EXPECT_LT(lateral, 0.018);
  EXPECT_LT(lateral_velocity, 2e-4);
}

// The observation is where the aligned position is in the TN plane (radial component ~0; the Sun
// moves 0.04 deg/h between t0 and t_obs), near the north pole for this orbit (u ~ 81 deg).
TEST(Guidance, ObservationIsInTheTnPlaneNearThePole) {
  const auto orbit = science_orbit(kChief, kEpoch);
  ASSERT_TRUE(orbit.ok());
  // measured regression bound: 0.022 m (2026-11); bound 0.05 m
  EXPECT_LT(std::abs(orbit->state_rtn[0]), 0.05);  // [m]
  // comment above: u ~ 81 deg; measured regression bound: 8.0 deg (2026-11); bound 15 deg
  EXPECT_NEAR(orbit->u_obs / core::kDegToRad, 90.0, 15.0);
}

// beta between -23.6 and -30.6 deg for this SSO over the year (sin beta = cos d sin i sin(RAAN -
// alpha) + sin d cos i with RAAN - alpha = -30 deg, LTAN 10:00, d = -/+23.44 deg;
// docs/algorithms/control.md#science-orbit). The tested -29.6 deg is an early-October estimate
// whose derivation is not recorded: the same formula with the early-October declination
// (-3.2 deg) gives -29.1 deg; measured here -28.9 deg at 2024-10-01. The 1 deg tolerance covers
// all three.
TEST(Guidance, SunElevationOverTheOrbitPlaneMatchesTheWorkedExample) {
  const auto orbit = science_orbit(kChief, kEpoch);
  ASSERT_TRUE(orbit.ok());
  EXPECT_NEAR(orbit->beta / core::kDegToRad, -29.6, 1.0);
}

// How the guidance relates to the paper's science ROE (Guffanti et al. 2023, Table 5;
// a*[-2.62, 45.21, -34.51, 4.78, -18.72, 2.72] m). Measured: ours a*[0.04, 35.23, -34.82, 4.91,
// -19.22, 2.70] m. The e and i vectors agree to 0.5 m: the paper's science orbit is this aligned
// orbit in its relative eccentricity and inclination. It differs in a*da = -2.62 m, which drifts dlambda by +24.7 m per
// orbit (3 pi a da), and in a*dlambda (+10 m, ~0.4 orbit of that drift): consistent with the
// paper listing the orbit before the observation, with a drift that carries it into alignment.
TEST(Guidance, ScienceOrbitComparedWithThePapersScienceRoe) {
  const auto orbit = science_orbit(kChief, kEpoch);
  ASSERT_TRUE(orbit.ok());
  const Eigen::Matrix<double, 6, 1> ours = kChief.a * orbit->roe;
  Eigen::Matrix<double, 6, 1> paper;
  paper << -2.62, 45.21, -34.51, 4.78, -18.72, 2.72;
  std::printf("science a*dROE [m]: ours (%.2f, %.2f, %.2f, %.2f, %.2f, %.2f), paper (%.2f, %.2f, %.2f, %.2f, %.2f, "
              "%.2f), difference %.2f m\n",
              ours[0], ours[1], ours[2], ours[3], ours[4], ours[5], paper[0], paper[1], paper[2], paper[3],
              paper[4], paper[5], (ours - paper).norm());
  // measured regression bound: 0.60 m (2026-11); bound 1 m
  EXPECT_LT((ours.segment<4>(2) - paper.segment<4>(2)).norm(), 1.0);  // e and i vectors [m]
}

TEST(Guidance, ScienceOrbitRejectsANonPositiveFocalDistance) {
  ScienceGeometry g;
  g.focal_distance_m = 0.0;
  EXPECT_EQ(science_orbit(kChief, kEpoch, g).error().field, "focal_distance_m");
}

// Waypoints keep the e and i vectors parallel (one common phase) and end at the target.
TEST(Guidance, TransferWaypointsKeepTheEAndIVectorsParallel) {
  const astro::RelativeOrbitalElements from = standby_roe(kChief.a);
  const auto orbit = science_orbit(kChief, kEpoch);
  ASSERT_TRUE(orbit.ok());
  const auto waypoints = transfer_waypoints(from, orbit->roe);
  ASSERT_TRUE(waypoints.ok()) << waypoints.error().describe();
  // precondition (start and end waypoints); measured 5 (2026-11)
  ASSERT_GE(waypoints->size(), 2u);
  for (std::size_t k = 0; k + 1 < waypoints->size(); ++k) {
    const auto& w = (*waypoints)[k];
    const double cross = w[roe::kDex] * w[roe::kDiy] - w[roe::kDey] * w[roe::kDix];
    // parallel by construction (one common phase), round-off; measured 0 (2026-11)
    EXPECT_NEAR(cross, 0.0, 1e-18) << "waypoint " << k;
  }
  EXPECT_EQ(waypoints->back(), orbit->roe);
}

// Each leg turns the common phase by at most max_phase_step.
TEST(Guidance, TransferLegsRespectTheMaximumPhaseStep) {
  const astro::RelativeOrbitalElements from = standby_roe(kChief.a);
  const astro::RelativeOrbitalElements to = standby_roe(kChief.a, {50.0, 2.9});
  const TransferSettings settings;
  const auto waypoints = transfer_waypoints(from, to, settings);
  ASSERT_TRUE(waypoints.ok());
  double previous = std::atan2(from[roe::kDey], from[roe::kDex]);
  for (const auto& w : *waypoints) {
    const double phase = std::atan2(w[roe::kDey], w[roe::kDex]);
    // settings.max_phase_step (documented setting) plus 1e-12 rad round-off; measured 0.332 rad vs 0.35 rad (2026-11)
    EXPECT_LE(std::abs(std::remainder(phase - previous, core::kTwoPi)), settings.max_phase_step + 1e-12);
    previous = phase;
  }
}

TEST(Guidance, TransferRejectsAZeroEVector) {
  astro::RelativeOrbitalElements bad = standby_roe(kChief.a);
  bad[roe::kDex] = bad[roe::kDey] = 0.0;
  EXPECT_EQ(transfer_waypoints(bad, standby_roe(kChief.a)).error().field, "from");
}

}  // namespace
}  // namespace visors::control
