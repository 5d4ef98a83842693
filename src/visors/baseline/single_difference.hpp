#pragma once
// Between-receiver single differences (rover minus base) of one satellite at one epoch, reduced
// by everything the models know: what is left is the rover position error's projection, the SD
// ambiguity (phase) and the noise. With P and L [m] the observables, rho the geometric range,
// dT the satellite clock, I the L1 ionosphere (x (f1/f2)^2 on L2), T the troposphere:
//   code  residual = (P_r - P_b) - [(rho_r - rho_b) - c (dT_r - dT_b) + (I_r - I_b) + (T_r - T_b)]
//   phase residual = (L_r - L_b) - [(rho_r - rho_b) - c (dT_r - dT_b) - (I_r - I_b) + (T_r - T_b)]
// (the receiver clocks are left in; they cancel between satellites). Their variances are the sum
// of the two receivers' undifferenced variances, sigma(el) = a + b / sin(el) per receiver
// (RTKLIB's elevation model, squared: a^2 + b^2 / sin^2 el).

#include <array>
#include <limits>

#include <Eigen/Core>

#include "visors/baseline/baseline_settings.hpp"
#include "visors/baseline/receiver_observables.hpp"
#include "visors/baseline/signal_model.hpp"

namespace visors::baseline {

/// Carrier wavelength of frequency 0 (L1) or 1 (L2) [m].
double wavelength_m(int frequency);

struct SingleDifference {
  int prn = 0;
  double elevation_rad = 0.0;  // at the rover
  double azimuth_rad = 0.0;    // at the rover
  Eigen::Vector3d los_rover = Eigen::Vector3d::Zero();  // unit, rover -> satellite (ECEF)
  std::array<double, kFrequencies> phase_m{};  // residual (file comment) [m]; NaN when absent
  std::array<double, kFrequencies> code_m{};   // residual [m]; NaN when absent
  std::array<double, kFrequencies> phase_var_m2{};  // [m^2]
  std::array<double, kFrequencies> code_var_m2{};   // [m^2]
};

/// The single difference of one satellite from both receivers' observables and signals.
/// Frequencies not in `settings.frequencies` are left NaN.
SingleDifference single_difference(const SatelliteObservables& rover, const SatelliteSignal& rover_signal,
                                   const SatelliteObservables& base, const SatelliteSignal& base_signal,
                                   const BaselineSettings& settings);

}  // namespace visors::baseline
