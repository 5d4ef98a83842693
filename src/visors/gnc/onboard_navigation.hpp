#pragma once
// The flight component's own navigation (`[navigation] mode = "cdgps"`): the carrier-phase
// differential GPS filter of nav/cdgps_filter.hpp fed from the component's channels, and the
// navigation solution the control stack and the safety check use (Guffanti et al., AAS 23-149,
// 2023, sec. 4.2).
//
// Inputs, as they arrive step by step:
//  - the GPS message: the own receiver's epoch, with the attitude of the time at tone at its time
//    tag, and the broadcast records the receiver decoded (gnss/ephemeris_store.hpp);
//  - the crosslink: the other receiver's epoch and attitude, the other spacecraft's executed
//    impulses and the OSC's rangefinder measurements;
//  - the own propulsion telemetry: the executed (commanded, quantised) impulse, in GCRF through
//    the attitude at its time.
// Joint epochs. The filter processes an epoch once both receivers' observations of that time tag
// are here: with a crosslink delay below the 1 s step, epoch t is processed at the step t + 1.
// An own epoch whose peer does not arrive within peer_wait_s is processed alone (GRAPHIC of the
// own receiver: relative accuracy is then kept by the held ambiguities and the dynamics only).
// Impulses executed before an epoch are applied before its update (at their time; one reported
// after the filter passed its time, late, at the current epoch with the drift it caused,
// CdgpsFilter::apply_impulse); an impulse at an epoch's own time comes after its measurements
// (the simulator measures, then fires).
// Cold start: nav/cold_start.hpp on the first joint epochs with enough satellites.
// Solution at the step's time: the last update's (fixed when its ambiguities were fixed, else
// float) carried to `now` by the filter's mean dynamics (CdgpsFilter::forecast), plus the
// impulses since that epoch; its relative covariance the update's P mapped to the relative
// state in the chief's RTN (not carried: 1-2 s of growth is far below the fixed solution's).
// Without any own epoch for coast_after_s (a GPS outage), the filter is predicted to each step,
// so the covariance grows and the estimate goes on from the dynamics.
//
// Allocation-free after create(); nothing throws.

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "visors/core/earth_frames.hpp"
#include "visors/core/eop.hpp"
#include "visors/core/status.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/gnc/messages.hpp"
#include "visors/gnss/ephemeris_store.hpp"
#include "visors/nav/cdgps_filter.hpp"
#include "visors/nav/cold_start.hpp"

namespace visors::gnc {

struct OnboardNavigationSettings {
  nav::CdgpsSettings filter;  // filter.local is set from the component's own spacecraft
  /// The GPS antenna of both spacecraft (one design), body frame: reference point from the
  /// nominal centre of mass, and the nominal phase-centre offset along the boresight +Z [m].
  Eigen::Vector3d antenna_arp_body_m = Eigen::Vector3d(0.0, 0.0, 0.1);
  double antenna_pco_m = 0.0854;
  /// The rangefinder (OSC) and its target (DSC), each from its centre of mass, body [m]; the
  /// range's noise and calibrated bias [m].
  Eigen::Vector3d lrf_lever_body_m = Eigen::Vector3d(0.15, 0.0, 0.0);
  double lrf_sigma_m = 0.002;
  double lrf_bias_m = 0.0;
  bool fuse_laser = true;
  /// An own epoch waits this long for the other receiver's over the crosslink [s].
  double peer_wait_s = 2.0;
  /// Without own epochs for this long the filter coasts (file comment) [s].
  double coast_after_s = 3.0;
  /// The solution is handed to the control and safety only while its relative position and
  /// velocity 1-sigma (root of the trace of each 3 x 3 block) are below these: not after the
  /// cold start until the carrier phase has converged it (the 10 m and 0.1 m/s priors make the
  /// passive-safety check see a collision risk), nor when a long outage has let it grow
  /// (the component then reports itself GNC incapable) [m, m/s].
  double valid_position_sigma_m = 0.1;
  double valid_velocity_sigma_mps = 1e-3;
  core::EarthOrientation earth_orientation;  // uplinked (the IERS values at the campaign's start)

  /// Ok, or the field by name.
  [[nodiscard]] core::Status validate() const;
};

// NavigationCounters, what the navigation did so far, are part of its telemetry (messages.hpp).

class OnboardNavigation {
 public:
  /// `dsc_model`, `osc_model`: the on-board force models (nav::CdgpsFilter::create).
  static core::Result<OnboardNavigation> create(const OnboardNavigationSettings& settings, Spacecraft self,
                                                dynamics::ForceModel dsc_model, dynamics::ForceModel osc_model);

  void add_ephemeris(const gnss::BroadcastEphemeris& record);
  /// The own receiver's epoch and the attitude at its time tag.
  void add_own_epoch(const nav::GpsReceiverEpoch& epoch, const Eigen::Quaterniond& q_body_to_gcrf);
  void add_own_impulse(const ExecutedImpulse& impulse);
  /// The OSC's own rangefinder measurement.
  void add_laser_range(const LaserRange& range);
  /// The other spacecraft's navigation data (its epoch, impulses, range).
  void add_peer(const CrosslinkNavigation& peer);

  /// Processes the complete epochs (file comment) and returns the solution at `now`, or nullopt
  /// before the cold start and while it is not valid (settings' valid_* sigmas).
  std::optional<NavigationSolution> solve(core::GpsTime now);

  /// What this spacecraft sends the other (its newest epoch, attitude, impulses, range).
  [[nodiscard]] const CrosslinkNavigation& crosslink() const { return outgoing_; }
  /// The solution of the last solve(), valid or not (nullopt before the cold start).
  [[nodiscard]] const std::optional<NavigationSolution>& last_solution() const { return solution_; }
  [[nodiscard]] bool initialised() const { return filter_.initialised(); }
  /// The time tag of the last measurement update (or of the cold start).
  [[nodiscard]] core::GpsTime last_update() const { return last_update_; }
  [[nodiscard]] bool fixed() const { return last_report_.fix_applied && fixed_current_; }
  /// The last solution met the settings' valid_* sigmas.
  [[nodiscard]] bool valid() const { return valid_; }
  [[nodiscard]] const nav::CdgpsEpochReport& last_report() const { return last_report_; }
  [[nodiscard]] const NavigationCounters& counters() const { return counters_; }
  [[nodiscard]] const nav::CdgpsFilter& filter() const { return filter_; }
  /// The navigation telemetry record (messages.hpp) of the last solve(); `now` tags it before
  /// the cold start. Allocation-free.
  [[nodiscard]] NavigationTelemetry telemetry(core::GpsTime now) const;

 private:
  static constexpr int kEpochs = 4;     // buffered epochs per receiver
  static constexpr int kImpulses = 8;   // impulses waiting for their epoch
  static constexpr int kRanges = 4;     // rangefinder measurements waiting for their epoch

  struct BufferedEpoch {
    bool filled = false;
    bool processed = false;
    nav::GpsReceiverEpoch epoch;
    Eigen::Matrix3d body_to_gcrf = Eigen::Matrix3d::Identity();
  };
  struct PendingImpulse {
    core::GpsTime t;
    nav::Craft craft = nav::Craft::kDsc;
    Eigen::Vector3d dv_gcrf_mps = Eigen::Vector3d::Zero();
  };

  OnboardNavigation(const OnboardNavigationSettings& settings, Spacecraft self, nav::CdgpsFilter filter);

  static void store(std::array<BufferedEpoch, kEpochs>& buffer, const nav::GpsReceiverEpoch& epoch,
                    const Eigen::Matrix3d& body_to_gcrf);
  BufferedEpoch* next_own_epoch();
  BufferedEpoch* peer_epoch(core::GpsTime t);
  void queue_impulse(core::GpsTime t, nav::Craft craft, const Eigen::Vector3d& dv_gcrf_mps);
  void queue_range(const LaserRange& range);
  void process(const BufferedEpoch& own, const BufferedEpoch* peer);
  void cold_start(const BufferedEpoch& own, const BufferedEpoch& peer);
  void apply_impulses_before(core::GpsTime t);
  void fuse_range(core::GpsTime t, const Eigen::Matrix3d& dsc_body_to_gcrf, const Eigen::Matrix3d& osc_body_to_gcrf);
  [[nodiscard]] nav::AntennaGeometry antenna(const Eigen::Matrix3d& body_to_gcrf) const;
  NavigationSolution solution(core::GpsTime now);

  OnboardNavigationSettings settings_;
  Spacecraft self_;
  nav::Craft local_, remote_;
  nav::CdgpsFilter filter_;
  core::OnboardEarthFrame frame_;
  gnss::EphemerisStore ephemerides_;
  nav::ColdStart cold_;
  std::array<BufferedEpoch, kEpochs> own_{}, peer_{};
  std::array<PendingImpulse, kImpulses> impulses_{};
  int impulse_count_ = 0;
  std::array<LaserRange, kRanges> ranges_{};
  int range_count_ = 0;
  bool have_peer_impulse_ = false;
  core::GpsTime last_peer_impulse_;
  bool have_range_ = false;
  core::GpsTime last_peer_range_;
  bool processed_any_ = false;
  core::GpsTime last_processed_;
  core::GpsTime last_update_;
  core::GpsTime last_own_epoch_;
  nav::CdgpsEpochReport last_report_{};
  bool fixed_current_ = false;  // the last report's fixed solution belongs to the filter's epoch
  CrosslinkNavigation outgoing_;
  std::optional<NavigationSolution> solution_;
  bool valid_ = false;
  NavigationCounters counters_;
};

/// A receiver epoch in the crosslink's form (gnc/messages.hpp) and back: the observations in
/// order, at most gnss::kMaxGpsChannels of them (the own receiver's channels).
CrosslinkEpoch crosslink_epoch(const nav::GpsReceiverEpoch& epoch);
nav::GpsReceiverEpoch receiver_epoch(const CrosslinkEpoch& epoch);

}  // namespace visors::gnc
