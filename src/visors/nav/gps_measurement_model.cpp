#include "visors/nav/gps_measurement_model.hpp"

namespace visors::nav {
namespace {

// Adds sign x the partials of one receiver's range to the row, scaled to the state units.
void add_range_partials(NavRow& h, Craft craft, const RangePrediction& range, double sign) {
  h.segment<3>(state::position(craft)) += sign * range.d_position;
  h.segment<3>(state::velocity(craft)) += sign * state::kVelocityUnit * range.d_velocity;
  h.segment<3>(state::phase_center(craft)) += sign * state::kPhaseCenterUnit * range.d_pco_error;
  h(state::clock(craft)) += sign * (1.0 + range.d_clock);  // c dt directly, and through t_r
}

}  // namespace

ReceiverEstimate receiver_estimate(const NavVector& x, Craft craft) {
  ReceiverEstimate e;
  e.r_gcrf_m = x.segment<3>(state::position(craft));
  e.v_gcrf_mps = state::kVelocityUnit * x.segment<3>(state::velocity(craft));
  e.clock_m = x(state::clock(craft));
  e.pco_error_body_m = state::kPhaseCenterUnit * x.segment<3>(state::phase_center(craft));
  return e;
}

MeasurementPrediction predict_graphic(const NavVector& x, Craft craft, const RangePrediction& range, int b_state) {
  MeasurementPrediction out;
  out.value_m = range.range_m + x(state::clock(craft)) - range.satellite_clock_m + x(b_state);
  add_range_partials(out.h, craft, range, 1.0);
  out.h(b_state) = 1.0;
  return out;
}

MeasurementPrediction predict_sd_code(const NavVector& x, const RangePrediction& osc, const RangePrediction& dsc) {
  MeasurementPrediction out;
  out.value_m = (osc.range_m - dsc.range_m) + (x(state::clock(Craft::kOsc)) - x(state::clock(Craft::kDsc))) -
                (osc.satellite_clock_m - dsc.satellite_clock_m);
  add_range_partials(out.h, Craft::kOsc, osc, 1.0);
  add_range_partials(out.h, Craft::kDsc, dsc, -1.0);
  return out;
}

MeasurementPrediction predict_sdcp(const NavVector& x, const RangePrediction& osc, const RangePrediction& dsc,
                                   int n_state, double wavelength_m) {
  MeasurementPrediction out = predict_sd_code(x, osc, dsc);
  out.value_m += wavelength_m * x(n_state);
  out.h(n_state) = wavelength_m;
  return out;
}

}  // namespace visors::nav
