#pragma once
// Kepler's equation M = E - e sin E for elliptic orbits (0 <= e < 1) and the conversions between
// mean (M), eccentric (E) and true (nu) anomaly [rad].
//
// The unchecked functions assume 0 <= e < 1 and finite angles (the caller validated them, e.g.
// through validate_keplerian()); solve_kepler() is the checked entry point. Every conversion keeps
// the revolution count of its input: the output differs from the input by a bounded, periodic
// amount (the equation of the centre), so a continuous M(t) maps to a continuous nu(t).

#include "visors/core/status.hpp"

namespace visors::astro {

/// Eccentric anomaly E with E - e sin E = mean_anomaly, for 0 <= e < 1. Unchecked.
double eccentric_from_mean(double mean_anomaly, double e);

/// Checked form of eccentric_from_mean: rejects e outside [0, 1) ("e") and a non-finite M ("M").
core::Outcome<double> solve_kepler(double mean_anomaly, double e);

double mean_from_eccentric(double eccentric_anomaly, double e);
double true_from_eccentric(double eccentric_anomaly, double e);
double eccentric_from_true(double true_anomaly, double e);
double true_from_mean(double mean_anomaly, double e);
double mean_from_true(double true_anomaly, double e);

}  // namespace visors::astro
