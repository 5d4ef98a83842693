#pragma once
// What `visors nav` reads from a `visors gnss-sim` run directory (file formats:
// sim/gnss_simulation.hpp).
// What the spacecraft know on board: the resolved scenario (the receivers' noise specification,
// the LRF's), both receivers' observations (RINEX 3: C1C, L1C and its loss-of-lock and
// half-cycle indicators), the broadcast ephemerides each receiver had decoded by then (brdc.rnx's
// records from the epochs of ephemeris_decoded.csv: nav/decoded_ephemerides.hpp), the commanded
// impulses (maneuvers.csv: the command, not the executed truth), the laser ranges (lrf.csv) and
// the attitude each bus's ADCS reported (attitude_reported.csv: the true attitude turned by the
// star tracker's error, 6 / 40 / 6 arcsec by default, sim/adcs_model.hpp; the antenna mounting
// errors, 30 arcsec, are in the measurements, unknown to the filter).
// For scoring only, the truth: each spacecraft's centre of mass in GCRF and its true attitude at
// the time tag (truth.csv), each channel's integer ambiguity and receiver phase offset
// (channels_truth.csv), from which the true double-difference integers follow, the observation
// windows (summary.json) and the centre-of-mass and payload-point draws of the run's seed.
// maneuvers.csv, lrf.csv and summary.json's "observations" are optional (runs of older versions);
// attitude_reported.csv and ephemeris_decoded.csv are not: a run without them (gnss-sim before the
// ADCS and the decoding delay) is refused naming the file, rather than replayed with the true
// attitude or every data set from its first broadcast, which the flight software never has.

#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/gnss/ephemeris_set.hpp"
#include "apps/nav/decoded_ephemerides.hpp"
#include "visors/nav/gps_observations.hpp"
#include "visors/nav/gps_range_model.hpp"
#include "visors/nav/laser_range_model.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::nav_app {

struct ChannelTruth {
  double single_difference_cycles = 0.0;  // ambiguity + receiver phase offset (per receiver)
};

/// One spacecraft at an epoch's time tag: the true centre of mass (GCRF) and attitude (scoring
/// only: the filter's attitude is RunInputs::known_attitude).
struct CraftTruth {
  core::StateVector x_gcrf;
  Eigen::Quaterniond body_to_gcrf = Eigen::Quaterniond::Identity();
  double receiver_clock_m = 0.0;  // c dt_r at the time tag [m]
};

/// A commanded impulse as the flight software knows it [s after the scenario start, GCRF m/s].
struct CommandedImpulse {
  double t_s = 0.0;
  nav::Craft craft = nav::Craft::kOsc;
  Eigen::Vector3d dv_gcrf_mps = Eigen::Vector3d::Zero();
};

/// An observation: the slew starts at slew_start_s, the observation spans [start_s, end_s] [s].
struct ObservationSpan {
  double slew_start_s = 0.0, start_s = 0.0, end_s = 0.0;
};

struct RunInputs {
  sim::CampaignScenario scenario;
  std::vector<nav::GpsReceiverEpoch> dsc, osc;  // in time order
  gnss::EphemerisSet ephemerides;  // brdc.rnx, screened
  /// Per receiver (DSC, OSC): brdc.rnx's records from the epoch it decoded each (ephemeris_decoded.csv).
  std::array<DecodedEphemerides, 2> decoded_ephemerides;
  /// The attitude each ADCS reported at each epoch's time tag, body to GCRF (attitude_reported.csv),
  /// DSC and OSC: what the flight software knows; key: ms after the scenario start.
  std::map<long long, std::array<Eigen::Quaterniond, 2>> known_attitude;
  std::vector<CommandedImpulse> impulses;  // in time order
  std::map<long long, double> laser_ranges_m;  // key: ms after the scenario start
  std::vector<ObservationSpan> observations;
  /// Truth at each epoch's time tag, DSC and OSC; key: ms after the scenario start.
  std::map<long long, std::array<CraftTruth, 2>> truth;
  /// Per epoch (ms) and PRN: the receiver's (integer ambiguity + phase offset) [cycles], DSC and OSC.
  std::map<long long, std::map<int, std::pair<double, double>>> phase_truth;
  /// True lever arm from the centre of mass to the antenna phase centre, body frame [m], DSC and
  /// OSC, as gnss-sim's summary.json records them (receivers.*.phase_center_body_m minus
  /// center_of_mass_body_m).
  std::array<Eigen::Vector3d, 2> true_antenna_lever_body_m{};
  /// The true payload reference point from the true centre of mass, body frame [m], DSC and OSC
  /// (the LRF's end points; the run's drawn geometry).
  std::array<Eigen::Vector3d, 2> true_payload_lever_body_m{};
};

/// Milliseconds after the scenario start: the key of the maps above.
inline long long key_ms(double t_s) { return std::llround(t_s * 1000.0); }

/// The antenna as the spacecraft knows it: the attitude (body to GCRF), the nominal centre of
/// mass, the antenna reference point and the phase-centre offset along the boresight (body +Z):
/// the flight software's calibrated values (the scenario's [flight]), not the truth's.
nav::AntennaGeometry antenna_geometry(const sim::FlightKnowledge& told, const Eigen::Quaterniond& body_to_gcrf);

/// The angular velocity of `craft`'s body (0: DSC, 1: OSC), GCRF [rad/s], at t_s [s after the
/// scenario start], from the attitudes the spacecraft know at the neighbouring epochs (the ADCS's
/// reports, one scenario step_s before and after): the rotation between them over their interval,
/// as gnss-sim defines the rate (its +-0.5 s there); one-sided at the ends of the run, zero when
/// neither neighbour is known. At a slew's start or end it is the mean rate over the interval. The
/// reports' white error enters it: 40 arcsec about body Y, differenced over 2 s, ~1.4e-4 rad/s.
Eigen::Vector3d known_angular_velocity_gcrf(const RunInputs& in, double t_s, std::size_t craft);

/// The laser range's end points as the spacecraft know them: the rangefinder's and its target's
/// levers from the nominal centres of mass and its calibrated bias (the scenario's [flight]: the
/// OSC's photon sieve, the DSC's detector), and the attitudes.
nav::LaserRangeGeometry laser_geometry(const sim::FlightKnowledge& told, const Eigen::Quaterniond& dsc_body_to_gcrf,
                                       const Eigen::Quaterniond& osc_body_to_gcrf);

/// The attitudes the spacecraft know at t_s (DSC, OSC), nullptr when the run has none then.
const std::array<Eigen::Quaterniond, 2>* known_attitudes_at(const RunInputs& in, double t_s);

/// Reads `run_dir`; errors name the file (and line).
core::Result<RunInputs> read_run(const std::filesystem::path& run_dir);

}  // namespace visors::nav_app
