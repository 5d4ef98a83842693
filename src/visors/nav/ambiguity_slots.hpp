#pragma once
// A bank of ambiguity slots in the navigation filter's fixed 98-state layout
// (docs/algorithms/cdgps-filter.md#ambiguity-slots): kGpsSlots consecutive states (the GRAPHIC bank
// B or the SDCP bank N, navigation_state.hpp) lent to GPS satellites while they are tracked. Fixed
// storage, a PRN -> slot map and an active mask: the matrix sizes never change and nothing is
// allocated, where a filter that inserts and deletes rows would reallocate at every rise and set.
//
// Rules kept by the bank:
// - a satellite rises (acquire): it takes the lowest free slot; its state gets the caller's prior
//   value and variance, its cross-covariances are zeroed (the "large variance" initialisation:
//   the new state is independent of the others until measured);
// - a satellite slips (reinitialise): the same in place, the slot keeps its PRN;
// - a satellite sets or is lost (release): marginalising a Gaussian is deleting the state's row
//   and column; here they are zeroed instead and the slot is parked: x = 0, P(s, s) =
//   kParkedVariance, P(s, j) = P(j, s) = 0 for j != s. The parked diagonal keeps P positive
//   definite and well conditioned (a zero would make it singular), and because the row and column
//   are zero the active states' (x, P) equal those of a filter that really deleted the state, as
//   long as inactive slots get no H entries and no process noise (the caller's part: measurement
//   rows are checked with row_on_active_only()).
// Activity is the mask alone. A state whose value is exactly 0.0 is not thereby inactive (unlike
// RTKLIB's filter(), which skips states equal to 0.0: a real state can be 0).
//
// consistent() checks every rule above on a filter's (x, P): an always-on invariant check.

#include <array>
#include <bit>
#include <cstdint>

#include "visors/core/result.hpp"
#include "visors/nav/navigation_state.hpp"

namespace visors::nav {

class AmbiguitySlotBank {
 public:
  static constexpr int kSlots = kGpsSlots;
  static constexpr int kMaxPrn = 32;  // GPS PRN 1..32 (as gnss::kMaxGpsPrn; nav uses core only)
  /// The diagonal of P at a parked (inactive) slot: harmless, keeps P well conditioned.
  static constexpr double kParkedVariance = 1.0;

  /// A bank whose slot 0 is filter state first_state: state::kGraphicAmbiguities or
  /// state::kSdcpAmbiguities (anything else is refused, naming "first_state"). Every slot starts
  /// inactive; the filter parks them in its (x, P) with release_all().
  static core::Result<AmbiguitySlotBank> create(int first_state);

  /// The active slots in increasing order: `for (int slot : bank.active_slots())`.
  class ActiveSlots {
   public:
    class Iterator {
     public:
      int operator*() const { return std::countr_zero(bits_); }
      Iterator& operator++() {
        bits_ &= bits_ - 1U;  // clears the lowest set bit, the slot just visited
        return *this;
      }
      bool operator==(const Iterator&) const = default;

     private:
      friend class ActiveSlots;
      explicit Iterator(std::uint32_t bits) : bits_(bits) {}
      std::uint32_t bits_;
    };
    [[nodiscard]] Iterator begin() const { return Iterator(bits_); }
    [[nodiscard]] Iterator end() const { return Iterator(0U); }

   private:
    friend class AmbiguitySlotBank;
    explicit ActiveSlots(std::uint32_t bits) : bits_(bits) {}
    std::uint32_t bits_;
  };

  [[nodiscard]] int first_state() const { return first_state_; }
  /// The slot of a tracked PRN; -1 when the PRN has none (or is outside 1..kMaxPrn).
  [[nodiscard]] int slot_of(int prn) const;
  /// The filter state of a slot (first_state() + slot); -1 for a slot outside 0..kSlots-1.
  [[nodiscard]] int state_of(int slot) const;
  /// Whether the slot holds a satellite; false for a slot outside 0..kSlots-1.
  [[nodiscard]] bool active(int slot) const;
  /// The PRN of an active slot; 0 when inactive or outside 0..kSlots-1.
  [[nodiscard]] int prn_of(int slot) const;
  [[nodiscard]] int active_count() const { return std::popcount(active_mask_); }
  [[nodiscard]] bool full() const { return active_count() == kSlots; }
  [[nodiscard]] ActiveSlots active_slots() const { return ActiveSlots(active_mask_); }

  /// A satellite rises: takes the lowest free slot s, zeroes row and column s of P, sets
  /// P(s, s) = variance and x(s) = value. Returns s; -1, with nothing changed, when the bank is
  /// full, the PRN is outside 1..kMaxPrn or already has a slot, value or variance is not finite,
  /// or variance <= 0.
  [[nodiscard]] int acquire(int prn, double value, double variance, NavVector& x, NavMatrix& P);

  /// A cycle slip: the same re-initialisation in place; the slot keeps its PRN. False, with
  /// nothing changed, when the slot is not active or value, variance are invalid as for acquire.
  [[nodiscard]] bool reinitialise(int slot, double value, double variance, NavVector& x, NavMatrix& P);

  /// The satellite set or was lost: zeroes row and column, parks the diagonal, x = 0, clears the
  /// PRN map, marks the slot inactive. False (nothing changed) when the slot is not active.
  bool release(int slot, NavVector& x, NavMatrix& P);

  /// Releases every slot and parks every state of the bank, active or not: the filter's
  /// initialisation and a bank reset. The bank is then empty and consistent with (x, P).
  void release_all(NavVector& x, NavMatrix& P);

  /// Whether a measurement row has no entry (non-zero, NaN included) on an inactive slot of this
  /// bank: inactive slots must not be measured (they would stop being independent of the rest).
  [[nodiscard]] bool row_on_active_only(const NavRow& h) const;

  /// x(state) = value, P(state, state) = variance, the rest of its row and column zero: a state
  /// independent of all others (a slot's start, or parked). Shared with the banks that follow
  /// these slots (nav/sd_multipath.hpp).
  static void set_independent(int state, double value, double variance, NavVector& x, NavMatrix& P);

  /// The bank's invariants on (x, P): every inactive slot has x = 0, P(s, s) = kParkedVariance
  /// and a zero row and column otherwise; every active slot has a finite x and a finite positive
  /// diagonal; the PRN map and the mask agree both ways.
  [[nodiscard]] bool consistent(const NavVector& x, const NavMatrix& P) const;

 private:
  explicit AmbiguitySlotBank(int first_state);
  [[nodiscard]] bool maps_agree() const;
  void set_state(int slot, double value, double variance, NavVector& x, NavMatrix& P) const;

  int first_state_;
  std::uint32_t active_mask_ = 0;          // bit s set: slot s active
  std::array<int, kSlots> prn_of_slot_{};  // 0 when inactive
  std::array<int, kMaxPrn + 1> slot_of_prn_{};  // -1 when none; entry 0 unused
};

}  // namespace visors::nav
