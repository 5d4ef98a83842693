#pragma once
// The single-difference carrier multipath of the navigation filter: one first-order Gauss-Markov
// state per SDCP slot (bank M of nav/navigation_state.hpp, in mm), so that the filter carries the
// multipath's correlation from one epoch to the next instead of treating it as white.
//
// Why: a patch antenna's carrier multipath changes as the line of sight turns in the antenna frame,
// over tens of seconds. Weighed as white noise, N epochs of it count as N independent ones: the
// relative position follows the multipath and the covariance is optimistic
// (docs/navigation-multipath.md). Inflating the weight instead (sdcp_correlation_inflation) trades
// that for a loss of the phase's short-term precision. A state per single difference is the exact
// model of a first-order error (state augmentation for coloured measurement noise: Brown & Hwang,
// Introduction to Random Signals and Applied Kalman Filtering, the chapter on coloured measurement
// noise).
//
// Model, per slot s with SD multipath m (OSC minus DSC, the two receivers' independent errors):
//
//   m(t + dt) = phi m(t) + w,   phi = exp(-dt / tau),   var(w) = (1 - phi^2) sigma_s^2,
//   sigma_s^2 = sigma_zenith^2 (1 / sin^2 E_osc + 1 / sin^2 E_dsc) / 2,
//
// sigma_zenith the SD's steady-state sigma at the zenith of both antennas (sqrt(2) times one
// receiver's), E the elevations above the antenna planes as the SDCP's elevation weighting floors
// them (its variance_scale): the multipath grows as 1 / sin E like the noise. sigma_s follows the
// elevations as they change (set at each measurement, used by the next time update).
//
// Life of a state, kept in step with its N slot by the filter: started (x = 0, variance sigma_s^2,
// row and column zeroed: independent of the rest) whenever its ambiguity is (re)initialised (a
// rise, a flagged or detected slip: the receiver's tracking restarts and the multipath is drawn
// anew); parked like its slot (x = 0, P(s, s) = AmbiguitySlotBank::kParkedVariance, row and column
// zero) when the slot is released. Inactive slots get no process noise and no H entries.
//
// Allocation-free; sigma_zenith = 0 disables the bank (every state stays parked).

#include <array>

#include "visors/nav/ambiguity_slots.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

class SdMultipathStates {
 public:
  /// sigma_zenith_m >= 0 [m], tau_s > 0 [s] (checked with the filter's settings, cdgps_settings.hpp).
  SdMultipathStates(double sigma_zenith_m, double tau_s) : sigma_zenith_m_(sigma_zenith_m), tau_s_(tau_s) {}

  [[nodiscard]] bool enabled() const { return sigma_zenith_m_ > 0.0; }
  /// The filter state of slot s's multipath.
  static constexpr int state_of(int slot) { return state::kSdMultipath + slot; }

  /// The slot's steady-state variance from this epoch's elevations (variance_scale as the SDCP's
  /// elevation weighting computes it: (1 / sin^2 E_osc + 1 / sin^2 E_dsc) / 2, 1 without weighting).
  void set_elevation_scale(int slot, double variance_scale);
  /// (Re)starts the slot's state: x = 0, its steady-state variance, independent of the rest.
  void start(int slot, NavVector& x, NavMatrix& P) const;
  /// Parks the slot's state with its released ambiguity.
  static void park(int slot, NavVector& x, NavMatrix& P);
  /// The time update over dt [s] of the states of the active SDCP slots: x and the rows and
  /// columns of P times phi, the diagonal plus (1 - phi^2) sigma_s^2.
  void propagate(const AmbiguitySlotBank& sdcp, double dt, NavVector& x, NavMatrix& P) const;

 private:
  [[nodiscard]] double steady_variance_units(int slot) const;  // sigma_s^2 in state units [mm^2]

  double sigma_zenith_m_;
  double tau_s_;
  std::array<double, kGpsSlots> scale_{};  // per slot: the variance_scale of its last measurement
};

}  // namespace visors::nav
