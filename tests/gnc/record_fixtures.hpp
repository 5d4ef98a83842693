#pragma once
// One message of every channel, each field a value of its own (magnitudes of a converged
// formation; only their bits matter): the records the codec tests encode, decode and pin
// (test_channel_record.cpp, test_record_schema.cpp and its golden files).

#include "visors/core/gps_time.hpp"
#include "visors/gnc/channel_record.hpp"

namespace visors::gnc::test {

inline core::GpsTime t0() { return core::GpsTime::parse("2024-10-01T00:00:00", core::TimeScale::kGps).value(); }

inline TimeAtTone tone() { return {t0() + 1.5, Eigen::Quaterniond(0.5, -0.5, 0.5, 0.5)}; }

inline NavigationSolution navigation() {
  NavigationSolution m;
  m.t = t0() + 2.0;
  m.chief_gcrf = {Eigen::Vector3d(6878137.0, -1.5, 2.25), Eigen::Vector3d(0.1, 7612.6, -0.2)};
  m.deputy_gcrf = {Eigen::Vector3d(6878140.0, 39.0, 3.0), Eigen::Vector3d(0.1, 7612.61, -0.21)};
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) m.relative_covariance_rtn(i, j) = 1e-6 * (1 + i + j) + (i == j ? 1e-4 : 0.0);
  }
  return m;
}

inline CrosslinkMessage crosslink() {
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

inline GroundCommand command() { return {t0() + 4.0, GroundCommand::Kind::kStartScience, 10}; }

inline PropulsionTelemetry propulsion() { return {t0() + 5.0, Eigen::Vector3d(0.001, -0.002, 0.0005), 11.2, true}; }

// A GPS message with three channels and a broadcast record (values of a real 2024 record's
// magnitudes; only their bits matter here).
inline GpsMessage gps(bool with_ephemeris = true) {
  GpsMessage m;
  m.t = t0() + 6.0;
  m.epoch.t = m.t;
  m.epoch.channel_count = 3;
  for (int k = 0; k < 3; ++k) {
    gnss::GpsChannelMeasurement& c = m.epoch.channels[static_cast<std::size_t>(k)];
    c.prn = 5 + 7 * k;
    c.pseudorange_m = 2.1e7 + 1234.5678 * k;
    c.carrier_phase_cycles = 1.1e8 + 0.123 * k;
    c.doppler_hz = -1234.5 + k;
    c.cn0_dbhz = 45.0 + k;
    c.lock_time_s = 100.0 * k;
    c.loss_of_lock = k == 1;
    c.half_cycle_ambiguity = k == 2;
  }
  m.has_ephemeris = with_ephemeris;
  if (with_ephemeris) {
    gnss::BroadcastEphemeris& e = m.ephemeris;
    e.prn = 12;
    e.toc = e.toe = t0() - 600.0;
    e.transmission = t0() - 3000.0;
    e.af0_s = -1.2e-4;
    e.af1_sps = 3e-12;
    e.iode = e.iodc = 77;
    e.sqrt_a = 5153.6;
    e.eccentricity = 0.0081;
    e.i0_rad = 0.96;
    e.omega0_rad = -2.1;
    e.omega_rad = 1.3;
    e.m0_rad = 0.4;
    e.delta_n_radps = 4.5e-9;
    e.omega_dot_radps = -8.1e-9;
    e.cuc_rad = 1e-6;
    e.crs_m = 40.0;
    e.tgd_s = -1.1e-8;
    e.ura_m = 2.0;
  }
  return m;
}

inline LaserRange laser() { return {t0() + 7.0, 40.0123}; }

inline ManeuverCommand maneuver() { return {t0() + 8.0, Eigen::Vector3d(1e-3, -2e-4, 3e-5), Eigen::Vector3d(-4e-4, 1e-3, 2e-5)}; }

inline ObservationCommand observation() { return {t0() + 9.0, 4, t0() + 100.0, t0() + 250.0, t0() + 260.0}; }

inline Telemetry telemetry() {
  Telemetry m;
  m.t = t0() + 10.0;
  m.mode = Mode::kScience;
  m.active = true;
  m.estimate_valid = true;
  m.gnc_incapable = false;
  m.lrf_power = true;
  m.passive_safety_violated = true;
  m.roe_mean_m << 0.1, 35.0, -34.0, 5.0, -19.0, 2.8;
  m.safety_margin_m = 12.5;
  m.roe_target_m << 0.0, 40.0, 0.0, 0.0, 0.0, 0.0;
  m.observations_done = 3;
  m.pending_pieces = 17;
  m.plans = 1234;
  m.planning_failures = 2;
  m.rejected.count(RejectionReason::kTooOld, Channel::kGps);
  m.rejected.count(RejectionReason::kNotFinite, Channel::kLaserRange);
  m.rejected.count(RejectionReason::kNoAttitude, Channel::kGps);
  for (int k = 0; k < 42; ++k) m.rejected.count(RejectionReason::kBadChecksum, Channel::kNavigation);
  m.rejected.count(RejectionReason::kBadMagic, 0);
  m.navigation_valid = true;
  m.navigation_fixed = true;
  m.navigation_update = t0() + 9.0;
  m.drag_valid = true;
  m.differential_drag_mps2 = -1.25e-6;
  return m;
}

// A navigation telemetry record after a full fix of three double differences (values of a
// converged formation's magnitudes; only their bits matter here).
inline NavigationTelemetry navigation_telemetry() {
  NavigationTelemetry m;
  m.t = t0() + 11.0;
  m.has_solution = m.valid = m.fixed = m.fix_applied = m.full_fix = true;
  m.dsc_gcrf = {Eigen::Vector3d(6878137.0, -1.5, 2.25), Eigen::Vector3d(0.1, 7612.6, -0.2)};
  m.osc_gcrf = {Eigen::Vector3d(6878140.0, 39.0, 3.0), Eigen::Vector3d(0.1, 7612.61, -0.21)};
  m.p_dsc_body_m = Eigen::Vector3d(1e-3, -2e-3, 4e-3);
  m.p_osc_body_m = Eigen::Vector3d(-3e-3, 5e-4, -1e-3);
  m.empirical_dsc_rtn_mps2 = Eigen::Vector3d(1e-8, -2e-7, 3e-9);
  m.empirical_osc_rtn_mps2 = Eigen::Vector3d(-4e-8, 5e-7, -6e-9);
  m.relative_sigma_rtn_m = Eigen::Vector3d(7e-4, 9e-4, 6e-4);
  m.update_t = t0() + 10.0;
  m.dd_reference_prn = 17;
  m.dd_count = 3;
  m.dd[0] = FixedDoubleDifference{3, -12, -12.0000000001};
  m.dd[1] = FixedDoubleDifference{22, 7, 7.0};
  m.dd[2] = FixedDoubleDifference{31, 1234567890123, 1234567890123.0};
  m.counters.epochs_joint = 86000;
  m.counters.epochs_alone = 400;
  m.counters.epochs_refused = 2;
  m.counters.epochs_fixed = 86300;
  m.counters.wrong_fixes_refused = 1;
  m.counters.impulses_applied = 30;
  m.counters.impulses_late = 3;
  m.counters.laser_used = 50;
  m.counters.laser_rejected = 4;
  m.counters.clock_jumps = 5;
  m.counters.ephemerides = {400, 1, 2, 3000, 4, 5};
  return m;
}

// A crosslink with its navigation part: the sender's epoch of two observations, its attitude,
// two impulses and a range.
inline CrosslinkMessage crosslink_with_navigation() {
  CrosslinkMessage m;
  m.t = t0() + 3.0;
  m.sender = Spacecraft::kOsc;
  m.mode = Mode::kScience;
  m.sender_active = true;
  CrosslinkNavigation& n = m.navigation;
  n.has_epoch = true;
  n.epoch.t = t0() + 2.0;
  n.epoch.count = 2;
  n.epoch.observations[0] = CrosslinkObservation{3, 2.2e7, 1.15e8, true, false};
  n.epoch.observations[1] = CrosslinkObservation{31, 2.3e7, 1.2e8, false, true};
  n.q_body_to_gcrf = Eigen::Quaterniond(0.5, 0.5, -0.5, 0.5);
  n.impulse_count = 2;
  n.impulses[0] = ExecutedImpulse{t0() + 1.0, Eigen::Vector3d(1e-3, 2e-3, -3e-4)};
  n.impulses[1] = ExecutedImpulse{t0() - 45.5, Eigen::Vector3d(-1e-3, 0.0, 5e-4)};
  n.has_range = true;
  n.range = LaserRange{t0() + 2.0, 39.987};
  return m;
}


// A partial fix of two integer combinations of the three double differences: each combination's
// coefficients (negative and beyond 16 bits too) and integer come back.
inline NavigationTelemetry partial_fix_telemetry() {
  NavigationTelemetry m = navigation_telemetry();
  m.full_fix = false;
  for (FixedDoubleDifference& d : m.dd) d.integer_cycles = 0;
  m.combination_count = 2;
  m.combinations[0] = FixedCombination{{1, -1, 0}, -19};
  m.combinations[1] = FixedCombination{{-70000, 3, 2}, 840002469134};
  return m;
}

/// The message of each channel the golden records hold (tests/gnc/golden/channel_<n>.txt).
template <class Message>
Message record_fixture();
template <> inline TimeAtTone record_fixture() { return tone(); }
template <> inline NavigationSolution record_fixture() { return navigation(); }
template <> inline CrosslinkMessage record_fixture() {
  CrosslinkMessage m = crosslink();  // its observation fields, and the navigation part
  m.navigation = crosslink_with_navigation().navigation;
  return m;
}
template <> inline GroundCommand record_fixture() { return command(); }
template <> inline PropulsionTelemetry record_fixture() { return propulsion(); }
template <> inline GpsMessage record_fixture() { return gps(); }
template <> inline LaserRange record_fixture() { return laser(); }
template <> inline ManeuverCommand record_fixture() { return maneuver(); }
template <> inline ObservationCommand record_fixture() { return observation(); }
template <> inline Telemetry record_fixture() { return telemetry(); }
template <> inline NavigationTelemetry record_fixture() { return partial_fix_telemetry(); }

}  // namespace visors::gnc::test
