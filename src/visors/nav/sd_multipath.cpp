#include "visors/nav/sd_multipath.hpp"

#include <cmath>

namespace visors::nav {

void SdMultipathStates::set_elevation_scale(int slot, double variance_scale) {
  scale_[static_cast<std::size_t>(slot)] = variance_scale;
}

double SdMultipathStates::steady_variance_units(int slot) const {
  const double sigma = sigma_zenith_m_ / state::kMultipathUnit;
  return sigma * sigma * scale_[static_cast<std::size_t>(slot)];
}

void SdMultipathStates::start(int slot, NavVector& x, NavMatrix& P) const {
  if (!enabled()) return;
  AmbiguitySlotBank::set_independent(state_of(slot), 0.0, steady_variance_units(slot), x, P);
}

void SdMultipathStates::park(int slot, NavVector& x, NavMatrix& P) {
  AmbiguitySlotBank::set_independent(state_of(slot), 0.0, AmbiguitySlotBank::kParkedVariance, x, P);
}

void SdMultipathStates::propagate(const AmbiguitySlotBank& sdcp, double dt, NavVector& x, NavMatrix& P) const {
  if (!enabled() || !(dt > 0.0)) return;
  const double phi = std::exp(-dt / tau_s_);
  const double one_minus_phi2 = -std::expm1(-2.0 * dt / tau_s_);
  for (int slot : sdcp.active_slots()) {
    const int s = state_of(slot);
    x(s) *= phi;
    P.row(s) *= phi;
    P.col(s) *= phi;
    P(s, s) += one_minus_phi2 * steady_variance_units(slot);
  }
}

}  // namespace visors::nav
