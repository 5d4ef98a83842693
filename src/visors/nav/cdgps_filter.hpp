#pragma once
// The carrier-phase differential GPS navigation filter each spacecraft runs on board (Guffanti
// et al., AAS 23-149, 2023, sec. 4.2; docs/algorithms/cdgps-filter.md): one extended Kalman
// filter estimating both
// spacecraft (nav/navigation_state.hpp: 98 states), from the local receiver's GRAPHIC and the
// SDCP of the satellites both receivers track (the remote receiver's phase comes over the
// crosslink), with integer ambiguity resolution on the double differences of the SDCP
// ambiguities.
//
// Epoch cycle (the caller's order): predict(t) to the measurements' time tag; apply_impulse() for
// maneuvers executed since; update() with the epoch's observations:
// 0. Receiver clock jumps (a receiver steering its clock by a millisecond moves all its code and
//    phase at once): the epoch's median GRAPHIC (local receiver) or SD code (remote) beyond its
//    own gate is taken into that clock state (absorb_clock_jump in cdgps_filter.cpp).
// 1. Ambiguity slots (nav/ambiguity_slots.hpp): a satellite new to a bank, or flagged by the
//    loss-of-lock indicator, gets its slot (re)initialised at its code value (GRAPHIC minus
//    code, SD phase minus SD code) with the prior variance (large-variance method,
//    docs/algorithms/cdgps-filter.md#ambiguity-slots), so the same measurement then updates
//    it; a satellite unmeasured for longer than slot_timeout_s is released (a lost crosslink epoch
//    or a short gap keeps the ambiguity, and with it a held integer). A phase flagged with an
//    unresolved half cycle is not used (the receiver flags the loss of lock when it resolves it).
// 2. Sequential scalar updates (nav/scalar_update.hpp, Joseph form): GRAPHIC first, then the SD
//    code of the common satellites averaged into one scalar (those within the gate of the
//    median's innovation; it fixes the clock difference, CdgpsSettings::sd_code), then SDCP,
//    each predicted once per epoch at the prior state and linearised there (the innovation of a
//    later scalar is corrected by h (x - x_prior)), in consensus order: the scalar whose
//    innovation is the epoch's median first, so that a slipped or blundered one cannot capture
//    the nearly free receiver clock (optionally weighted by the elevation, CdgpsSettings). A rejected SDCP is a cycle slip the indicator
//    missed: its slot is reinitialised and the measurement processed again (it then only sets the
//    new ambiguity); a rejected GRAPHIC is a code outlier and is dropped. The codes (GRAPHIC, SD
//    code) are weighed by their white-equivalent variance and gated on their per-epoch one
//    (CdgpsSettings::code_multipath_sigma_m, graphic_variance, sd_code_variance). An SDCP is weighed by
//    its per-epoch variance times sdcp_correlation_inflation (correlated multipath) and gated on
//    the per-epoch variance alone; its row has +1 on its slot's SD multipath state (started with
//    the ambiguity, parked with the slot: nav/sd_multipath.hpp). The phase-centre states have a gain only along the body axes
//    an attitude turn has just exposed; otherwise they are consider states
//    (docs/phase-centre-estimation.md).
// 3. Integer ambiguity resolution: the SDCP slots updated this epoch (of the satellites above
//    min_fix_elevation_deg at both antennas) form double differences
//    against the one with the most epochs of continuous lock (nav/double_difference.hpp); the
//    acceptance of nav/ambiguity_acceptance.hpp (success rate and ratio, partial fixing) decides;
//    the fixed solution is the float state conditioned on the fixed integers
//    (nav/fixed_solution.hpp), refused when an SDCP residual then fails the gate (wrong fix,
//    docs/algorithms/cdgps-filter.md#wrong-fix-check). With hold, an accepted full fix is also fed
//    back into the float filter as a pseudo-measurement, each fixed combination while its float
//    variance exceeds the hold variance (once, in effect: re-holding it every epoch would make P
//    over-confident); an SDCP of a held satellite that later fails its gate reinitialises that
//    slot, which releases the held integer (the wrong-fix recovery).
//
// Time update: the mean of each spacecraft by RK4 under its on-board force model plus the
// empirical acceleration (nav/orbit_time_update.hpp); the covariance with the short-step
// transition and the Gauss-Markov noise of the empirical acceleration (nav/gauss_markov.hpp), a
// random-walk receiver clock; phase-centre errors and ambiguities constant; the SD multipath
// states first-order Gauss-Markov.
//
// Allocation-free after create(); no exception; inputs checked (nav/gps_observations.hpp) and a
// bad epoch refused with its reason in the report.

#include <array>
#include <cstdint>
#include <memory>

#include "visors/core/earth_frames.hpp"
#include "visors/core/gps_time.hpp"
#include "visors/core/state_vector.hpp"
#include "visors/core/result.hpp"
#include "visors/dynamics/force_model.hpp"
#include "visors/gnss/ephemeris_source.hpp"
#include "visors/nav/ambiguity_acceptance.hpp"
#include "visors/nav/cdgps_settings.hpp"
#include "visors/nav/gps_observations.hpp"
#include "visors/nav/gps_range_model.hpp"
#include "visors/nav/laser_range_model.hpp"
#include "visors/nav/navigation_state.hpp"
#include "visors/nav/scalar_update.hpp"

namespace visors::nav {

struct CdgpsEpochInput {
  const GpsReceiverEpoch* dsc = nullptr;  // the DSC receiver's epoch (local or crosslinked), or none
  const GpsReceiverEpoch* osc = nullptr;  // the OSC receiver's
  AntennaGeometry dsc_antenna;
  AntennaGeometry osc_antenna;
};

struct CdgpsEpochReport {
  bool accepted = false;       // false: the epoch was refused (reason) and nothing changed
  const char* reason = "";     // "not_initialised", "time_tag", "dsc", "osc" (the failing input)
  int graphic_used = 0, graphic_rejected = 0;
  int sdcp_used = 0, sdcp_rejected = 0;
  int sd_code_used = 0, sd_code_rejected = 0;  // satellites in the averaged SD code; outliers left out
  int new_ambiguities = 0;     // slots (re)initialised: rises, flagged and detected slips
  int detected_slips = 0;      // SDCP gate failures (slips the indicator did not flag)
  int missing_ephemeris = 0;
  int ephemeris_switches = 0;  // GRAPHIC biases widened for a new broadcast data set of their satellite
  int clock_jumps = 0;         // receiver clock jumps taken into the clock states (the local's, the remote's)
  int implausible_observations = 0;  // skipped (nav/gps_observations.hpp plausible())
  int half_cycle_skipped = 0;        // phases flagged with an unresolved half cycle, not used
  double nis_sum = 0.0;        // sum of the accepted scalars' normalised innovations squared
  int nis_count = 0;
  double graphic_nis_sum = 0.0;  // the GRAPHIC part of nis_sum (graphic_used scalars)
  double sdcp_nis_sum = 0.0;     // the SDCP part of nis_sum (sdcp_used scalars)
  int double_differences = 0;
  int phase_centre_axes_estimated = 0;  // body axes of the phase-centre states with a gain this epoch (the others: consider states)
  /// The satellites of this epoch's double differences: the reference, then the others.
  std::array<int, kGpsSlots> dd_prns{};
  /// The fixed integer of each double difference, aligned with dd_prns (element 0, the reference's,
  /// unused): the SD ambiguity (OSC minus DSC) of dd_prns[j] minus that of dd_prns[0], L1 [cycles],
  /// j = 1..double_differences. Set when a full fix is applied (fix.outcome kFixed and
  /// fix_applied), else 0: a partial fix constrains integer combinations, not single DDs.
  std::array<std::int64_t, kGpsSlots> dd_integer_cycles{};
  /// The integer combinations a partial fix constrains (fix.outcome kPartial and fix_applied,
  /// else fixed_combinations = 0), in the double-difference space of dd_prns, so that a ground
  /// tool can judge them against its truth: combination i is
  ///   sum over j = 1..double_differences of combination_coefficients[i][j] DD_j = combination_integers[i]
  /// [cycles], DD_j the double difference of dd_prns[j] (element 0 unused), i = 0..fixed_combinations-1.
  /// The coefficients are the columns of the decorrelating transformation Z the fix searched
  /// (nav/integer_least_squares.hpp); a combination with a coefficient outside the int32 range
  /// (never met) leaves fixed_combinations at 0: that partial fix is then not judged.
  int fixed_combinations = 0;
  std::array<std::array<std::int32_t, kGpsSlots>, kGpsSlots> combination_coefficients{};
  std::array<std::int64_t, kGpsSlots> combination_integers{};
  AmbiguityFix fix{};
  bool fix_applied = false;    // the fixed solution is valid for this epoch (x_fixed())
  bool wrong_fix_refused = false;
  bool held = false;           // the fix was fed back into the float filter
};

class CdgpsFilter {
 public:
  /// `dsc_model` and `osc_model`: each spacecraft's on-board force model (drag area, mass).
  /// The error names the settings field.
  static core::Result<CdgpsFilter> create(const CdgpsSettings& settings, dynamics::ForceModel dsc_model,
                                          dynamics::ForceModel osc_model);

  /// Starts at t from absolute states (e.g. single-point solutions) and receiver clocks [m], with
  /// the settings' prior sigmas; every ambiguity slot empty.
  void initialise(core::GpsTime t, const core::StateVector& dsc_gcrf, const core::StateVector& osc_gcrf,
                  double dsc_clock_m, double osc_clock_m);
  [[nodiscard]] bool initialised() const;

  /// Time update to t >= epoch() (nothing when equal).
  void predict(core::GpsTime t);
  /// A commanded impulse dv (GCRF) [m/s] of `craft`, executed at the current epoch: added to the
  /// velocity, and its execution covariance (settings' impulse_*_sigma) to P:
  ///   sigma_m^2 dv dv' + (sigma_d |dv|)^2 (I - u u'),  u = dv / |dv|.
  /// An impulse reported late, executed elapsed_s >= 0 before the current epoch, also moves the
  /// position by dv elapsed_s (with the execution covariance mapped there); the epoch's gravity
  /// acting on the change over elapsed_s (~1e-5 m at 2 s) is neglected.
  /// False (nothing changed) for a non-finite dv or elapsed_s, a negative elapsed_s, or before
  /// initialise().
  bool apply_impulse(Craft craft, const Eigen::Vector3d& dv_gcrf_mps, double elapsed_s = 0.0);
  /// Measurement update at the current epoch (the observations' time tag).
  CdgpsEpochReport update(const CdgpsEpochInput& input, const gnss::EphemerisSource& ephemerides,
                          core::OnboardEarthFrame& frame);

  /// One laser-rangefinder range z [m] at the current epoch (nav/laser_range_model.hpp), noise
  /// sigma [m], gated like the GPS scalars; applied to the float filter, and to the fixed solution
  /// of this epoch when there is one. The outcome (accepted, rejected: an outlier, or invalid).
  ScalarUpdateStatus update_laser_range(double z_m, double sigma_m, const LaserRangeGeometry& geometry);

  [[nodiscard]] core::GpsTime epoch() const;
  [[nodiscard]] const NavVector& x() const;
  [[nodiscard]] const NavMatrix& P() const;
  /// The fixed solution of the last update (valid when its report says fix_applied).
  [[nodiscard]] const NavVector& x_fixed() const;
  [[nodiscard]] const NavMatrix& P_fixed() const;
  /// The satellites holding an SDCP slot: PRN and ambiguity state index, `count` of them.
  struct SlotList {
    int count = 0;
    std::array<int, kGpsSlots> prn{};
    std::array<int, kGpsSlots> state{};
  };
  [[nodiscard]] SlotList sdcp_slots() const;
  /// SI state of one spacecraft's centre of mass from x (or x_fixed()).
  [[nodiscard]] static core::StateVector centre_of_mass(const NavVector& x, Craft craft);

  /// The solution `from` (x() or x_fixed()) carried from epoch() to t >= epoch() by the mean
  /// dynamics of the time update, x and P untouched: what the estimate says of t when the
  /// measurements of epoch() are the last processed (a crosslink delay, the control's instant).
  /// Up to kShortForecastS ahead by nav::forecast_mean (one force evaluation per spacecraft;
  /// 7e-6 m from the RK4 at 1 s absolute, 1e-9 relative), beyond by the time update's RK4.
  /// Allocation-free.
  static constexpr double kShortForecastS = 2.0;
  [[nodiscard]] NavVector forecast(const NavVector& from, core::GpsTime t);
  [[nodiscard]] const CdgpsSettings& settings() const { return settings_; }

  CdgpsFilter(CdgpsFilter&&) noexcept;
  CdgpsFilter& operator=(CdgpsFilter&&) noexcept;
  ~CdgpsFilter();

 private:
  struct Impl;
  CdgpsFilter(const CdgpsSettings& settings, std::unique_ptr<Impl> impl);
  CdgpsSettings settings_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace visors::nav
