#include "visors/nav/ambiguity_slots.hpp"

#include <cmath>

namespace visors::nav {

namespace {

bool valid_prior(double value, double variance) {
  return std::isfinite(value) && std::isfinite(variance) && variance > 0.0;
}

std::uint32_t bit(int slot) { return std::uint32_t{1} << static_cast<unsigned>(slot); }

}  // namespace

core::Result<AmbiguitySlotBank> AmbiguitySlotBank::create(int first_state) {
  if (first_state != state::kGraphicAmbiguities && first_state != state::kSdcpAmbiguities) {
    return core::Error{"first_state", "must be state::kGraphicAmbiguities or state::kSdcpAmbiguities"};
  }
  return AmbiguitySlotBank(first_state);
}

AmbiguitySlotBank::AmbiguitySlotBank(int first_state) : first_state_(first_state) { slot_of_prn_.fill(-1); }

int AmbiguitySlotBank::slot_of(int prn) const {
  if (prn < 1 || prn > kMaxPrn) return -1;
  return slot_of_prn_[prn];
}

int AmbiguitySlotBank::state_of(int slot) const {
  if (slot < 0 || slot >= kSlots) return -1;
  return first_state_ + slot;
}

bool AmbiguitySlotBank::active(int slot) const {
  if (slot < 0 || slot >= kSlots) return false;
  return (active_mask_ & bit(slot)) != 0U;
}

int AmbiguitySlotBank::prn_of(int slot) const { return active(slot) ? prn_of_slot_[slot] : 0; }

// x(s) = value, P(s, s) = variance, the rest of row and column s zero: the state is independent of
// all others (the large-variance initialisation zeroes the cross-covariances), or parked when
// released.
void AmbiguitySlotBank::set_independent(int state, double value, double variance, NavVector& x, NavMatrix& P) {
  P.row(state).setZero();
  P.col(state).setZero();
  P(state, state) = variance;
  x(state) = value;
}

void AmbiguitySlotBank::set_state(int slot, double value, double variance, NavVector& x, NavMatrix& P) const {
  set_independent(first_state_ + slot, value, variance, x, P);
}

int AmbiguitySlotBank::acquire(int prn, double value, double variance, NavVector& x, NavMatrix& P) {
  if (prn < 1 || prn > kMaxPrn || slot_of_prn_[prn] >= 0 || full() || !valid_prior(value, variance)) return -1;
  // The lowest free slot: the lowest zero bit of the mask (the mask has kSlots < 32 bits).
  const int slot = std::countr_one(active_mask_);
  set_state(slot, value, variance, x, P);
  active_mask_ |= bit(slot);
  prn_of_slot_[slot] = prn;
  slot_of_prn_[prn] = slot;
  return slot;
}

bool AmbiguitySlotBank::reinitialise(int slot, double value, double variance, NavVector& x, NavMatrix& P) {
  if (!active(slot) || !valid_prior(value, variance)) return false;
  set_state(slot, value, variance, x, P);
  return true;
}

bool AmbiguitySlotBank::release(int slot, NavVector& x, NavMatrix& P) {
  if (!active(slot)) return false;
  set_state(slot, 0.0, kParkedVariance, x, P);
  slot_of_prn_[prn_of_slot_[slot]] = -1;
  prn_of_slot_[slot] = 0;
  active_mask_ &= ~bit(slot);
  return true;
}

void AmbiguitySlotBank::release_all(NavVector& x, NavMatrix& P) {
  for (int slot = 0; slot < kSlots; ++slot) set_state(slot, 0.0, kParkedVariance, x, P);
  active_mask_ = 0;
  prn_of_slot_.fill(0);
  slot_of_prn_.fill(-1);
}

bool AmbiguitySlotBank::row_on_active_only(const NavRow& h) const {
  for (int slot = 0; slot < kSlots; ++slot) {
    if (!active(slot) && h(first_state_ + slot) != 0.0) return false;  // NaN != 0 is true
  }
  return true;
}

// Mask -> map: an active slot's PRN is valid and maps back to it; an inactive slot holds PRN 0.
// Map -> mask: a PRN's slot, if any, is active and holds that PRN. Together: a bijection between
// the active slots and the PRNs with a slot.
bool AmbiguitySlotBank::maps_agree() const {
  if ((active_mask_ >> kSlots) != 0U) return false;
  for (int slot = 0; slot < kSlots; ++slot) {
    const int prn = prn_of_slot_[slot];
    if (!active(slot)) {
      if (prn != 0) return false;
    } else if (prn < 1 || prn > kMaxPrn || slot_of_prn_[prn] != slot) {
      return false;
    }
  }
  for (int prn = 1; prn <= kMaxPrn; ++prn) {
    const int slot = slot_of_prn_[prn];
    if (slot != -1 && (!active(slot) || prn_of_slot_[slot] != prn)) return false;
  }
  return slot_of_prn_[0] == -1;
}

bool AmbiguitySlotBank::consistent(const NavVector& x, const NavMatrix& P) const {
  if (!maps_agree()) return false;
  for (int slot = 0; slot < kSlots; ++slot) {
    const int s = first_state_ + slot;
    if (active(slot)) {
      if (!std::isfinite(x(s)) || !std::isfinite(P(s, s)) || !(P(s, s) > 0.0)) return false;
      continue;
    }
    if (x(s) != 0.0 || P(s, s) != kParkedVariance) return false;
    for (int j = 0; j < kNavStates; ++j) {
      if (j != s && (P(s, j) != 0.0 || P(j, s) != 0.0)) return false;
    }
  }
  return true;
}

}  // namespace visors::nav
