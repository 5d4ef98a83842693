#pragma once
// The operations of a `visors gnss-sim` run, planned before it starts from the [gnss.observations],
// [gnss.maneuvers] and [gnss.lrf] tables (sim/gnss_settings.hpp; what they do to the truth:
// sim/gnss_simulation.hpp).
//
// Observation windows (attitude = "campaign" only; none otherwise): start_k = first_start_s +
// k period, end_k = start_k + duration_s, slew_start_k = start_k - lead, for k = 0, 1, ... while
// slew_start_k < the run's last epoch. period = period_s, or the chief's Keplerian period
// 2 pi sqrt(a^3 / mu) (a = [chief] a_m, mu of core::EarthGravityConstants) when
// period_s = 0; lead = slew_lead_s, or AttitudeProfile::required_slew_lead_s(pi) (a 180 deg slew
// plus settling) when slew_lead_s = 0.
//
// Maneuver pieces: burst j (j = 0, 1, ...) at first_burst_s + j period / bursts_per_orbit, its
// pieces i = 0 .. pieces_per_burst - 1 at that time + i spacing_s ([propulsion] spacing, 46.5 s),
// those before the run's last epoch. Direction: bursts 2m and 2m+1 form a pair; burst 2m gets a
// unit vector u_m drawn once, isotropically (three normals, normalised), from
// RandomStream(seed, "gnss.maneuvers"), burst 2m+1 gets -u_m, so that each pair cancels to first
// order and the formation does not drift away over a long run. Each piece's commanded dv is
// dv_mps u in the maneuvering spacecraft's own RTN frame (at the impulse instant). spacecraft =
// "both": every piece is flown by both spacecraft at the same instant, the OSC with +u and the
// DSC with -u (each in its RTN frame), so the relative effect doubles and the pair's mean motion
// is barely changed. A piece whose time lies in [slew_start_s, end_s + 150 s] of an observation
// window is skipped (not commanded: no thrusting during a slew, the observation, or the 150 s
// after it), and counted.
// The pieces planned here are the random part only; keeping = true adds a tangential correction
// to each at execution time (sim/gnss_simulation.hpp, sim/formation_keeping.hpp).
//
// Laser rangefinder epochs (enabled only, attitude = "campaign"): in each window, the first
// epoch of the step_s grid at or after start_s, then every interval_s (a multiple of step_s)
// up to end_s. When start_s lies on the grid (e.g. integer first_start_s and period_s at 1 Hz)
// these are the epochs with fmod(t_s - start_s, interval_s) == 0; the chief's Keplerian period
// is not an integer, so later windows begin between epochs and the first measurement is the
// next epoch.
//
// Errors name the key: first_start_s below the lead ("gnss.observations.first_start_s"), a period
// not exceeding duration_s + lead ("gnss.observations.period_s"), a burst longer than the burst
// spacing ("gnss.maneuvers.pieces_per_burst": pieces_per_burst spacing_s must not exceed
// period / bursts_per_orbit), an interval that is not a multiple of step_s ("gnss.lrf.interval_s").

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "visors/core/result.hpp"
#include "visors/sim/attitude_profile.hpp"
#include "visors/sim/campaign_scenario.hpp"

namespace visors::sim {

/// One commanded maneuver piece.
struct GnssManeuverPiece {
  double t_s = 0.0;        // impulse time [s after t0]
  int craft = 1;           // 0 = DSC, 1 = OSC
  int burst = 0;           // burst index j
  Eigen::Vector3d dv_rtn_mps = Eigen::Vector3d::Zero();  // commanded, the craft's RTN frame [m/s]
};

struct GnssOperations {
  double period_s = 0.0;      // the observation (and burst) period used [s]
  double slew_lead_s = 0.0;   // the lead used [s]
  std::vector<ObservationWindow> windows;
  std::vector<GnssManeuverPiece> pieces;  // ordered by (t_s, craft)
  int skipped_pieces = 0;                 // pieces (per spacecraft) skipped for an observation
  std::vector<std::int64_t> lrf_epochs;   // epoch indices k (t_s = k step_s), increasing
};

/// Pieces within this long after an observation's end are skipped [s].
inline constexpr double kManeuverQuietAfterObservation_s = 150.0;

/// Plans the run's operations; `last_epoch_s` is the time of the run's last epoch, `profile` gives
/// the default slew lead. Errors: file comment.
core::Result<GnssOperations> plan_gnss_operations(const CampaignScenario& scenario, const AttitudeProfile& profile,
                                                  double last_epoch_s);

}  // namespace visors::sim
