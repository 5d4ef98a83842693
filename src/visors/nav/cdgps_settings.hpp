#pragma once
// Every tunable of the carrier-phase differential GPS filter (nav/cdgps_filter.hpp), with its
// default and unit; the algorithm each one enters: docs/algorithms/cdgps-filter.md. Receiver
// noise: the mission's receiver as simulated in Guffanti et al., AAS 23-149, 2023, sec. 5 (20 cm
// code, 2 mm phase, undifferenced).


#include "visors/core/status.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

struct CdgpsSettings {
  Craft local = Craft::kDsc;  // whose receiver gives the GRAPHIC measurements (the one running it)

  // Dynamics (docs/algorithms/cdgps-filter.md#time-update).
  double max_step_s = 10.0;                // RK4 step of the mean [s]
  double empirical_tau_s = 600.0;          // Gauss-Markov correlation time [s]
  // Its steady-state sigma, each RTN axis [m/s^2], in two parts: one common to both spacecraft
  // (the on-board model's errors 40 m apart are the same: gravity beyond 20x20, the density) and
  // one of each alone (what differs: drag and SRP areas, thrust leaks, and the 40 m gradient of
  // the gravity beyond 20x20, a few 1e-9 m/s^2). The common part gives the absolute orbits their
  // model error without loosening the relative dynamics, which see only the own parts
  // (docs/algorithms/cdgps-filter.md#empirical-accelerations).
  double empirical_common_sigma_mps2 = 5e-7;
  double empirical_sigma_mps2 = 1e-7;
  // The own part's along-track axis [m/s^2], when it differs from the others; negative:
  // empirical_sigma_mps2. The differential drag is along-track and reaches 1e-6 m/s^2 at solar
  // maximum (docs/drag-prediction.md). With the multipath states below the filter trusts its
  // dynamics over the minute, so the along-track axis needs room for that drag, and not so much
  // that the relative velocity wanders (docs/decisions.md, "Gauss-Markov states of the SD
  // multipath"; docs/navigation-multipath.md).
  double empirical_along_track_sigma_mps2 = 4e-7;
  double clock_random_walk_m = 10.0;       // receiver clock random walk, per sqrt(s) [m/sqrt(s)]
  // Random walk of each GRAPHIC bias [m/sqrt(s)]: the broadcast orbit and clock errors along a
  // line of sight change over a pass (the line of sight turns by ~0.3 rad in 30 min), which a
  // constant bias cannot follow; 0: constant biases. With it the GRAPHIC normalised innovations
  // stay consistent along the orbit (docs/algorithms/cdgps-filter.md#graphic-biases).
  double graphic_bias_random_walk_m = 1e-3;
  // Change of a satellite's broadcast range error when its data set changes (every 2 h), 1-sigma
  // [m]: added to its GRAPHIC bias at the switch. gnss-sim's sets jump by ~0.3 m (its
  // refresh_correlation 0.95 on ~1 m along a line of sight); real consecutive sets, 0.1-0.5 m.
  double ephemeris_switch_sigma_m = 0.5;
  // Execution errors of a commanded impulse (apply_impulse), 1-sigma: along the command, as a
  // fraction of |dv| (5 %, the low end of the propulsion's 5-50 % magnitude error, Guffanti et al.,
  // AAS 23-149, 2023, Table 1b), and the direction error across it. The direction default bounds
  // the same table's 0.05-10 deg range (sim/propulsion.hpp) at 1 deg: over-bounding costs a few
  // seconds of SDCP updates, under-bounding turns a maneuver into false cycle slips.
  double impulse_magnitude_sigma = 0.05;   // [-]
  double impulse_direction_sigma_deg = 1.0;  // [deg]

  // Priors at initialise() and for new ambiguities (docs/algorithms/cdgps-filter.md#ambiguity-slots:
  // a large variance, then the same measurement updates them).
  double position_sigma_m = 10.0;
  double velocity_sigma_mps = 0.1;
  double clock_sigma_m = 100.0;
  // Prior of the phase-centre states, each body axis [m]: the uncertainty of the antenna's
  // calibration as the flight team states it (a CubeSat patch antenna's phase centre is known to
  // a few mm: docs/truth-and-knowledge.md). The states start at zero (the calibrated value). A
  // body-fixed lever is what the centre of mass's knowledge error is too; the measurements tell
  // them apart only through the attitude's turns (docs/decisions.md, "The phase centre is
  // uncertain"; docs/phase-centre-estimation.md).
  double phase_center_sigma_m = 5e-3;
  // The phase-centre states as consider states between attitude turns. With both spacecraft in the
  // same attitude, fixed in the orbital frame, C (p_osc - p_dsc) is a constant RTN offset between
  // the antennas and the centres of mass; along-track it is a free relative orbit, so the data
  // cannot tell it from the centres of mass, and estimated states drift with whatever along-track
  // error they are handed (docs/phase-centre-estimation.md). They get a gain only from a turn of
  // either spacecraft's attitude in its orbital frame faster than phase_center_turn_rate_deg_s (a
  // slew: the antenna offset jumps, the centres of mass cannot) until
  // phase_center_free_after_turn_s after it, and only along the body axes the turn exposes (normal
  // to its axis); otherwise their estimate is held at what the last turns gave (the calibration
  // before any) while their covariance and correlations are carried (Schmidt consider states,
  // Joseph form). false: always estimated.
  bool phase_center_consider_between_turns = true;
  double phase_center_turn_rate_deg_s = 0.5;  // [deg/s]: the slews turn at 1.5, the nominal attitude at < 0.1
  double phase_center_free_after_turn_s = 300.0;  // [s]
  // Whether the offset along the boresight (body Z) is estimated at all (with the states held
  // between turns). Only the observation slews expose it, and in the nominal attitude it lies
  // along the radial, where the antennas' GPS error is largest: estimated, it takes up that error
  // during the slews; held at the calibration it keeps only the calibration's error
  // (docs/phase-centre-estimation.md, "The boresight component").
  bool phase_center_boresight_estimated = false;
  // New ambiguities start at their code value (cdgps_filter.cpp, start_ambiguities): GRAPHIC
  // minus code, off by the code's ionospheric delay (2-5 m at 500 km in 2024) and noise; SD
  // phase minus SD code, off by the SD code's noise (0.3 m: 1.5 cycles) and multipath.
  double graphic_ambiguity_sigma_m = 10.0;
  double sdcp_ambiguity_sigma_cycles = 100.0;
  // A slot is kept while its satellite goes unmeasured (a lost crosslink epoch, a data gap) and
  // released after this long [s]; a satellite back in time keeps its ambiguity unless the
  // loss-of-lock indicator or the innovation gate says it slipped.
  double slot_timeout_s = 30.0;

  // Measurements (docs/algorithms/gnss-measurements.md#graphic and #single-differences):
  // GRAPHIC = (code + phase) / 2, SDCP = phase OSC - DSC.
  // The white 0.1 m noise of (code + phase)/2 (0.2 m code); the broadcast orbit and clock errors
  // (~1 m) go to the bias B: their constant part over a pass at the start, their change through
  // graphic_bias_random_walk_m (not into this sigma: as white noise they would make the
  // innovations' consistency depend on time).
  double graphic_sigma_m = 0.1;
  double sdcp_sigma_m = 0.00283;           // sqrt(2) x 2 mm
  // Variance factor of an SDCP in the float filter's update, >= 1: the SD phase's multipath is
  // correlated from one epoch to the next (structure multipath changes as the line of sight turns
  // in the antenna frame, over tens of seconds), so N epochs carry the information of fewer
  // independent ones: N (1 - phi) / (1 + phi) for a first-order Gauss-Markov error, phi =
  // exp(-1 s / tau). Weighed as white, the float filter follows the multipath's rate into its
  // relative velocity. The innovation gate (slip detection) and the wrong-fix check keep the
  // per-epoch sdcp_sigma_m: inflating them would let a cycle slip or a wrong integer through.
  // 1: white, the default since the multipath has its states below (12 without them:
  // docs/navigation-multipath.md).
  double sdcp_correlation_inflation = 1.0;
  // The SD phase's multipath as Gauss-Markov states, one per SDCP slot (nav/sd_multipath.hpp):
  // the SD's steady-state sigma at both antennas' zenith [m] (grown as 1 / sin(elevation) with the
  // elevation weighting) and its correlation time [s]. 0: no states (the multipath is then part of
  // the white sdcp_sigma_m, weighed with sdcp_correlation_inflation). With the states,
  // sdcp_sigma_m is the white part alone and the inflation should be 1. Defaults: sqrt(2) x 2 mm
  // and 60 s, the flight team's characterisation of its patch antenna, equal to the nominal of
  // the truth's receiver (which draws no other). What the states and a mismatch of these
  // settings are worth: docs/navigation-multipath.md.
  double sdcp_multipath_sigma_m = 0.00283;
  double sdcp_multipath_tau_s = 60.0;
  double gate_sigmas = 5.0;                // scalar innovation gate [innovation sigmas]
  // The SD code (nav/gps_measurement_model.hpp) of the satellites both receivers track, averaged
  // into one scalar per epoch: it ties the clock difference to the codes at every epoch. Without
  // it the remote clock is held by the float SD ambiguities' common part, set by their code
  // start (start_ambiguities) and moved as satellites are handed over; c dt off by 40 m puts the
  // remote antenna 7.6 km/s x 133 ns = 1 mm along-track. sd_code_sigma_m: sqrt(2) x the 0.2 m
  // code noise, per satellite.
  bool sd_code = true;
  double sd_code_sigma_m = 0.3;
  // The code's multipath, each receiver: its first-order Gauss-Markov steady-state sigma at the
  // zenith [m] (grown as 1 / sin(elevation) with the elevation weighting) and its correlation
  // time [s]. The code has no states for it (24 more would cost what the SDCP's 12 did, for
  // measurements whose position information the phase dwarfs once fixed); it is weighed instead
  // as what N correlated epochs are worth, by code_variance below: the GRAPHIC and SD code
  // updates with the white-equivalent variance, their gates and the clock-jump test with the
  // per-epoch one. Weighed as white (0: the noise sigmas above alone), a minute of correlated
  // code errors counts as sixty independent ones: the float solution follows them and believes
  // them, and the phase innovations then fail their gates against it as false slips
  // (docs/navigation-multipath.md "Code multipath"). Defaults: the flight team's
  // characterisation of its patch antenna, equal to the nominal of the truth's receiver.
  double code_multipath_sigma_m = 0.3;
  double code_multipath_tau_s = 60.0;
  // Elevation weighting: each receiver's code and phase sigma divided by the sine of the
  // satellite's elevation above the antenna plane, floored at min_weighting_elevation_deg. On: a
  // patch antenna's noise and multipath grow towards the horizon, which the flight team knows of
  // its receiver (a flight choice, not read from the simulator's truth; docs/truth-and-knowledge.md).
  bool elevation_weighting = true;
  double min_weighting_elevation_deg = 5.0;

  // Integer ambiguity resolution (docs/algorithms/ambiguity-resolution.md#acceptance and
  // #fixed-solution-update); off: the float filter alone.
  bool ambiguity_resolution = true;
  // No fix attempt until the float filter has run this long after its cold start [s]. After a
  // cold start the broadcast records arrive one per second as the receiver decodes them (18-36 s
  // after lock), so the first epochs hold few satellites whose float ambiguities have not
  // converged, and a fix attempted then can be wrong (docs/decisions.md, "Broadcast records
  // arrive as a receiver decodes them"). RTKLIB's demo5 waits similarly (arminfix, arthres1).
  double min_float_s_before_fix = 30.0;
  // Elevation mask of the integer resolution [deg]: a satellite lower than this above either
  // antenna's plane stays in the float solution, unfixed (RTKLIB's arelmask). Multipath grows as
  // 1 / sin(elevation) (2 mm at the zenith is 11.5 mm at 10 deg, 23 mm at 5 deg), and a float
  // ambiguity biased by a few hundredths of a cycle passes the acceptance test with a wrong
  // integer. 0: every satellite tracked.
  double min_fix_elevation_deg = 15.0;
  AcceptanceSettings acceptance{};
  // Fix-and-hold: accepted full fixes fed back into the float filter, each fixed combination once,
  // as a pseudo-measurement of this variance. A DD ambiguity is an integer exactly, so the hold
  // is nearly hard (3e-4 cycles, 0.06 mm): the float state then keeps the fixed accuracy through
  // epochs without SDCP (crosslink drops, outages), the better the tighter the hold
  // (docs/algorithms/ambiguity-resolution.md#fix-and-hold). RTKLIB's holdamb uses 1e-3 but again
  // at every epoch, which tightens the same way over ~1000 epochs and costs an update of k rows
  // each time.
  bool hold = true;
  double hold_variance_cycles2 = 1e-7;     // [cycles^2]
};

/// Each value checked; the error names the field.
core::Status check(const CdgpsSettings& settings);

/// The variance at the zenith [m^2] of one code scalar, white noise plus multipath
/// (code_multipath_sigma_m): per epoch (`gate`: innovation gates, clock-jump test) and as the
/// update weighs it (`weight`: the multipath's variance times white_equivalent_factor at the
/// filter's 1 Hz, i.e. what a stream of correlated epochs is worth as white ones).
struct CodeVariance {
  double gate = 0.0;    // [m^2]
  double weight = 0.0;  // [m^2]
};
/// GRAPHIC = (code + phase) / 2 of one receiver: graphic_sigma_m^2 + (multipath / 2)^2.
CodeVariance graphic_variance(const CdgpsSettings& settings);
/// SD code of one satellite, two receivers: sd_code_sigma_m^2 + 2 multipath^2.
CodeVariance sd_code_variance(const CdgpsSettings& settings);

}  // namespace visors::nav
