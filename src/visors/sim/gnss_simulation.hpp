#pragma once
// `visors gnss-sim`: raw GPS measurements of both spacecraft along the scenario's truth orbits
// (formation flying freely: no control), for testing navigation filters and for processing with
// other GNSS software.
//
// The world: the scenario's truth force model (RK4 at integration_step_s) for both spacecraft from
// their initial states; commanded attitude nominal (antenna at the zenith), observation (payload
// +X at the Sun) or campaign ([gnss] attitude: nominal, with the observation windows of
// [gnss.observations], planned with the flight software's slew rate and settling
// (gnc.science), flown through sim::AttitudeProfile with eigen-axis slews at the ADCS's own
// [attitude] slew_rate_deg_s, 1.5 deg/s, as in `visors run`), held by each bus turned by its
// ADCS's control error and reported turned by its determination error (sim/adcs_model.hpp,
// [attitude], RandomStream(seed, "<craft>.adcs") stepped once an epoch: `visors run`'s draws);
// the true centre of mass and payload point drawn as in `visors run` (same seed, same geometry); optionally a maneuver schedule ([gnss.maneuvers]) and a laser rangefinder
// ([gnss.lrf]), planned as sim/gnss_operations.hpp says; the GPS constellation of [gnss] nav_file moved to the scenario start
// (gnss/constellation.hpp) with broadcast errors (sim/gps_satellite_truth.hpp); one receiver per
// spacecraft (sim/gps_receiver.hpp) with the navigation file's Klobuchar coefficients as the truth
// ionosphere. Earth orientation: the force model's EOP file when it names one, else zero EOP
// (both the receiver geometry and the truth ITRF use the same).
//
// Output directory: scenario.toml (resolved), dsc.rnx and osc.rnx (RINEX 3.05 observations,
// C1C L1C D1C S1C, LLI bit 0 on loss of lock), brdc.rnx (RINEX 3.05 navigation: the broadcast
// ephemerides the receivers decode, i.e. with the broadcast errors), ephemeris_decoded.csv and
// attitude_reported.csv (what the flight software gets besides the RINEX files: below),
// truth.csv, channels_truth.csv,
// maneuvers.csv and lrf.csv (always written; a header line only when there is nothing to record)
// and summary.json (counts, t0, per receiver the body-frame phase centre, centre of mass and
// boresight [m, unit]; "observations": [{"slew_start_s", "start_s", "end_s"}, ...] (empty unless
// attitude = "campaign"), "observation_period_s", "maneuvers": {"dsc": n, "osc": n} executed
// pieces, "maneuver_pieces_skipped" (pieces x spacecraft not commanded: in an observation's
// quiet time), "lrf_measurements", per receiver "data_sets_decoded" (rows of
// ephemeris_decoded.csv), and with keeping = true "keeping_clamped_pieces").
//
// Truth attitude. Every use of the attitude (truth.csv quaternion, the drag area of the truth
// forces, the receiver's antenna pose, the maneuvers' body frame, the payload points of the
// rangefinder) is the true one: the commanded attitude, a function of (t_s, r, v, Sun) (the fixed
// target, or AttitudeProfile::body_to_gcrf(t_s, ...) for "campaign"), turned by the ADCS's control
// error of the epoch (a piece between epochs: the commanded attitude at its time, turned by the
// last epoch's error, drawn once a step). The angular velocity is the commanded attitude's, as in
// `visors run`: the rotation between the commanded attitudes at t_s - 0.5 s and t_s + 0.5 s
// (states there by two-body motion from the epoch's), divided by 1 s.
//
// Maneuvers (spacecraft != "none"; schedule, directions and skipping: sim/gnss_operations.hpp).
// Each piece is executed on the truth at its own time t_p (46.5 s spacing puts every other piece
// half-way between epochs): the craft's truth is propagated to t_p, the commanded dv (its RTN
// frame of the true state at t_p) is rotated to GCRF, then into the body frame of the true
// attitude at t_p; sim::Propulsion::execute (the scenario's [propulsion] settings, the craft's
// [dsc]/[osc] mass_kg and propellant_kg, RandomStream(seed, "<craft>.propulsion") as `visors run`:
// quantisation, 5 % magnitude, 0.05 deg direction, Isp drawn) gives the executed body dv, rotated
// back to GCRF with the same attitude and added to the velocity; propagation goes on to the next
// epoch. A piece at an epoch's time fires after that epoch's record (its truth.csv row is the
// state before the impulse). A command the propulsion refuses is an error of the run, naming
// gnss.maneuvers.dv_mps (impulse range, propellant). The mass change is not fed back to the truth
// forces (as in `visors run`).
//
// Formation keeping ([gnss.maneuvers] keeping = true; false by default, the run is then the one
// above). At the first commanded piece of each burst, sim::along_track_correction (sim/
// formation_keeping.hpp: equations, sources) reads the TRUE states of both spacecraft at that
// instant (a perfect-knowledge formation-keeping law, what a test harness for navigation needs;
// the other craft's truth is propagated there on a copy) and gives the deputy-equivalent
// tangential dv_T that brings the mean dlambda back to [formation] initial_roe_m's within an
// orbit, net of the tangential part of the random pieces still to fly in the burst's pair, plus
// sim::eccentricity_tangential_dv_mps's share that brings the mean (dex, dey) back within an orbit
// (bursts_per_orbit >= 3). dv_T is flown by the OSC
// (spacecraft = "osc"), as -dv_T by the DSC ("dsc"), or +dv_T/2 by the OSC and -dv_T/2 by the DSC
// ("both"), spread evenly over the craft's commanded pieces of the burst and added along the T
// axis of each piece's RTN command (the random part unchanged). Each piece's total goes through
// the propulsion model as above; the correction is clamped so that the total stays within the
// impulse range at the craft's current mass (summary "keeping_clamped_pieces"). maneuvers.csv's
// commanded columns are the total (random + correction).
//
// maneuvers.csv, one row per executed piece and spacecraft, in time order (DSC first at equal
// times):
//   t_s [s]                       impulse time, seconds since t0 (3 decimals)
//   spacecraft                    dsc or osc
//   dv_cmd_x_gcrf_mps, dv_cmd_y_gcrf_mps, dv_cmd_z_gcrf_mps [m/s]  commanded dv in GCRF: what the
//                                 flight software commanded (the RTN command in the true RTN
//                                 frame), what a filter may use (%.9f)
//   dv_x_gcrf_mps, dv_y_gcrf_mps, dv_z_gcrf_mps [m/s]  executed dv in GCRF, truth (%.9f)
//
// lrf.csv, one row per rangefinder epoch (enabled, attitude = "campaign"; epochs:
// sim/gnss_operations.hpp):
//   t_s [s]                       time tag, seconds since t0 (3 decimals)
//   range_m [m]                   measured: true_range_m + bias_m + N(0, sigma_m), the noise from
//                                 RandomStream(seed, "osc.lrf") (%.6f)
//   true_range_m [m]              |p_osc - p_dsc| at T, p = r_gcrf + A(q) (payload point - centre
//                                 of mass, body), the true payload points (sim/spacecraft_geometry
//                                 .hpp draws) and the true attitudes of truth.csv (%.6f)
//
// Instants. Every epoch has a time tag T = t0 + t_s (t0 = time.start_gps), the RINEX epoch, and
// the simulation takes it as TRUE GPS time: the state columns of truth.csv are at T, which is what
// a navigation filter estimates when it takes the time tags as GPS time. The receiver's clock is
// off by dt_r (receiver_clock_m = c dt_r), so the signals are received at T - dt_r and sent at
// T - dt_r - tau (tau = range_m / c): the geometry columns say which instant they refer to.
// Scoring a filter's centre of mass against the phase-centre columns would mix the two instants
// (|v| dt_r: ~3 mm along-track for a 100 m clock offset).
//
// truth.csv, one row per epoch and spacecraft (truth throughout; the time derivatives are with
// respect to the time tag):
//   t_s [s]                       time tag, seconds since t0 (3 decimals)
//   spacecraft                    dsc or osc
//   x_gcrf_m, y_gcrf_m, z_gcrf_m  centre of mass at T, GCRF [m] (0.1 mm)
//   vx_gcrf_mps, vy_gcrf_mps, vz_gcrf_mps  its velocity at T, GCRF [m/s] (1 um/s)
//   x_apc_itrf_m, y_apc_itrf_m, z_apc_itrf_m  antenna phase centre at the reception instant
//                                 T - dt_r, ITRF [m] (0.1 mm): R(T) (r_gcrf + A(q) (phase centre -
//                                 centre of mass, body)) - v_apc dt_r, R the GCRF-to-ITRF rotation
//                                 (the EOP above), v_apc its ITRF velocity; the start of range_m
//   receiver_clock_m [m]          c dt_r at T (receiver clock minus GPS time; > 0: the clock is
//                                 ahead, the signals were received earlier than T)
//   visible, tracked              satellites passing the visibility test at reception, and tracked
//   receiver_clock_rate_mps [m/s] d(c dt_r)/dt at T (the clock is linear between epochs; at an
//                                 epoch the mean of the adjacent slopes: sim/gps_receiver.hpp)
//   qw_body_to_gcrf, qx_body_to_gcrf, qy_body_to_gcrf, qz_body_to_gcrf  true attitude at T,
//                                 body to GCRF, Hamilton, scalar first (1e-10)
// attitude_reported.csv, one row per epoch and spacecraft: what the ADCS reported (the flight
// software's attitude; truth.csv's is for scoring):
//   t_s, spacecraft               as in truth.csv
//   qw_body_to_gcrf, qx_body_to_gcrf, qy_body_to_gcrf, qz_body_to_gcrf  at T, body to GCRF,
//                                 Hamilton, scalar first (1e-10): truth.csv's turned by the
//                                 ADCS's determination error, q_true (x) dq(theta_knowledge)
// ephemeris_decoded.csv, one row per receiver and broadcast data set it decoded, in time order
// (sim/navigation_message.hpp: the set in force, subframes 1-3 received whole since the later of
// the lock and the set's first broadcast, 18-36 s, each set once; the rule of `visors run`, whose
// one-record GPS message passes on one set a step where this file lists every set of the epoch):
//   t_s [s]                       the time tag of the first recorded epoch at which the receiver
//                                 had decoded the set (none in a data gap: nothing reaches the
//                                 flight software then)
//   spacecraft                    dsc or osc: whose receiver
//   prn, toe_week, toe_sow        the data set: PRN and t_oe (GPS week, seconds of week, 1 us), a
//                                 record of brdc.rnx
//   iode                          its issue of data
// channels_truth.csv, one row per epoch, spacecraft and tracked channel:
//   t_s, spacecraft               as in truth.csv
//   prn                           GPS PRN
//   range_m [m]                   rho: from the phase centre at reception (T - dt_r) to the
//                                 satellite at transmission (T - dt_r - tau; its true orbit, the
//                                 IS-GPS-200 evaluation of its true record), in the Earth-fixed
//                                 axes of the reception instant (Earth rotation during tau)
//   satellite_clock_m [m]         c dt^j at transmission: the true L1 C/A clock offset
//   ionosphere_m [m]              I: the L1 delay (code delayed, phase advanced), geometry at
//                                 reception, local time of T
//   ambiguity_cycles              N, the integer of this track
//   satellite_phase_cycles, receiver_phase_cycles  phi^j, phi_r: constant fractional offsets
//   elevation_antenna_deg [deg]   above the antenna plane (true boresight) at reception, of the
//                                 satellite's position 0.075 s before reception (the visibility
//                                 screen: within 2e-4 deg of the transmission instant's)
//   range_rate_mps, satellite_clock_rate_mps, ionosphere_rate_mps [m/s]  d/dt of range_m,
//                                 satellite_clock_m, ionosphere_m at T
//   half_cycle_cycles             0.5 while the phase carries an unresolved half cycle (RINEX LLI
//                                 bit 1 set; gnss.receiver.half_cycle_slip_probability), else 0
//   new_ambiguity                 1 when the phase ambiguity is new at this epoch (acquisition,
//                                 cycle slip, half cycle resolved), flagged in the RINEX file or not
//                                 (gnss.receiver.unflagged_slip_fraction)
//   code_multipath_m, phase_multipath_m [m]  the multipath errors in C1C and lambda L1C
//   recorded                      0 in a data gap (no RINEX record of this receiver at T), else 1
// so that (e_ noise; lambda the L1 wavelength; RINEX rounding 0.001 m, cycles, Hz):
//   C1C            = range_m + receiver_clock_m - satellite_clock_m + ionosphere_m + code_multipath_m + e_P
//   lambda L1C     = range_m + receiver_clock_m - satellite_clock_m - ionosphere_m
//                    + lambda (ambiguity_cycles + half_cycle_cycles + receiver_phase_cycles
//                              - satellite_phase_cycles) + phase_multipath_m + e_Phi
//   -lambda D1C    = range_rate_mps + receiver_clock_rate_mps - satellite_clock_rate_mps
//                    - ionosphere_rate_mps + e_D
// (tests/sim/test_gnss_simulation.cpp checks these relations and the phase centre's).
#include <filesystem>
#include <functional>

#include <nlohmann/json.hpp>

#include "visors/core/result.hpp"
#include "visors/sim/campaign_scenario.hpp"
#include "visors/sim/campaign_simulation.hpp"

namespace visors::sim {

struct GnssRunResult {
  nlohmann::json summary;
  std::filesystem::path dir;
};

/// Runs [gnss] duration_s of the scenario at its step_s. Errors: set-up (named field), files.
core::Result<GnssRunResult> run_gnss_simulation(const CampaignScenario& scenario, const std::filesystem::path& out_dir,
                                                const std::function<void(const RunProgress&)>& progress = {});

}  // namespace visors::sim
