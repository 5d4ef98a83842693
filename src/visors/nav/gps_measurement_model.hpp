#pragma once
// The filter's two GPS measurements as functions of its 98 states
// (docs/algorithms/gnss-measurements.md#graphic, #single-differences), built from the range
// predictions of nav/gps_range_model.hpp:
//
//   GRAPHIC of the local receiver k, satellite j (half the sum of code and phase: ionosphere-free
//   to first order, code noise halved, one float ambiguity B per track, in metres):
//     G = rho_k + c dt_k - c dt^j(t_tx,k) + B_j
//   SDCP, OSC minus DSC, satellite j (phase only, L1; the GPS clock cancels up to its drift over
//   the two transmission instants, which is kept; the differential ionosphere over 40 m and the
//   phase wind-up of identical attitudes are neglected):
//     dPhi = rho_osc - rho_dsc + c dt_osc - c dt_dsc - (c dt^j(t_tx,osc) - c dt^j(t_tx,dsc)) + lambda N_j
//   SD code, OSC minus DSC (the same without the ambiguity; the differential ionosphere, +I
//   here, is as negligible): dP = dPhi - lambda N_j. It is what fixes the clock difference in
//   absolute terms: the SDCP alone leave it in the common part of the float SD ambiguities.
//
// The rows are partial derivatives with respect to the scaled states (nav/navigation_state.hpp:
// velocity in mm/s, phase-centre error in mm): each SI partial times unit(state).

#include <Eigen/Core>

#include "visors/nav/gps_range_model.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {


struct MeasurementPrediction {
  double value_m = 0.0;  // predicted measurement [m]
  NavRow h = NavRow::Zero();  // d value / d x (scaled states)
};

/// The SI estimate of one spacecraft's block of x.
ReceiverEstimate receiver_estimate(const NavVector& x, Craft craft);

/// GRAPHIC of `craft`'s receiver from its range prediction and the state of its B slot.
MeasurementPrediction predict_graphic(const NavVector& x, Craft craft, const RangePrediction& range, int b_state);

/// SD code (OSC minus DSC) from both range predictions of the same satellite.
MeasurementPrediction predict_sd_code(const NavVector& x, const RangePrediction& osc, const RangePrediction& dsc);

/// SDCP (OSC minus DSC) from both range predictions of the same satellite and the state of its
/// N slot [cycles], wavelength lambda [m].
MeasurementPrediction predict_sdcp(const NavVector& x, const RangePrediction& osc, const RangePrediction& dsc,
                                   int n_state, double wavelength_m);

}  // namespace visors::nav
