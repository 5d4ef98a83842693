#include "visors/gnss/ephemeris_store.hpp"

#include <cmath>

namespace visors::gnss {

const char* to_string(EphemerisStore::AcceptStatus status) {
  using S = EphemerisStore::AcceptStatus;
  switch (status) {
    case S::kStored: return "stored";
    case S::kImplausible: return "implausible";
    case S::kUnhealthy: return "unhealthy";
    case S::kDuplicate: return "duplicate";
    case S::kStale: return "stale";
    case S::kInconsistent: return "inconsistent";
  }
  return "?";
}

EphemerisStore::AcceptStatus EphemerisStore::accept(const BroadcastEphemeris& record) {
  if (!validate(record).ok()) return AcceptStatus::kImplausible;
  Slots& slots = by_prn_[static_cast<std::size_t>(record.prn)];
  int oldest = 0;
  for (int k = 0; k < slots.count; ++k) {
    const BroadcastEphemeris& stored = slots.records[static_cast<std::size_t>(k)];
    if (stored.toe == record.toe && stored.iode == record.iode) return AcceptStatus::kDuplicate;
    if (std::abs(stored.toe.seconds_since(record.toe)) <= kNeighbourWindowS && !disagreement(stored, record).agrees()) {
      return AcceptStatus::kInconsistent;
    }
    if (stored.toe < slots.records[static_cast<std::size_t>(oldest)].toe) oldest = k;
  }
  const AcceptStatus stored = record.health == 0 ? AcceptStatus::kStored : AcceptStatus::kUnhealthy;
  if (slots.count < kRecordsPerPrn) {
    slots.records[static_cast<std::size_t>(slots.count++)] = record;
    return stored;
  }
  BroadcastEphemeris& replaced = slots.records[static_cast<std::size_t>(oldest)];
  if (record.toe < replaced.toe) return AcceptStatus::kStale;
  replaced = record;
  return stored;
}

const BroadcastEphemeris* EphemerisStore::select(int prn, core::GpsTime t) const {
  if (prn < 1 || prn > kMaxGpsPrn) return nullptr;
  const Slots& slots = by_prn_[static_cast<std::size_t>(prn)];
  const BroadcastEphemeris* best = nullptr;
  double best_distance = 0.0;
  for (int k = 0; k < slots.count; ++k) {
    const BroadcastEphemeris& e = slots.records[static_cast<std::size_t>(k)];
    if (e.health != 0) continue;
    const double distance = std::abs(t.seconds_since(e.toe));
    const bool later = best != nullptr && e.transmission > best->transmission;
    if (best == nullptr || distance < best_distance || (distance == best_distance && later)) {
      best = &e;
      best_distance = distance;
    }
  }
  return best != nullptr && within_fit_interval(*best, t) ? best : nullptr;
}

int EphemerisStore::count(int prn) const {
  return prn >= 1 && prn <= kMaxGpsPrn ? by_prn_[static_cast<std::size_t>(prn)].count : 0;
}

int EphemerisStore::satellites() const {
  int n = 0;
  for (int prn = 1; prn <= kMaxGpsPrn; ++prn) n += by_prn_[static_cast<std::size_t>(prn)].count > 0 ? 1 : 0;
  return n;
}

}  // namespace visors::gnss
