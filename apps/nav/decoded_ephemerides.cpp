#include "apps/nav/decoded_ephemerides.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/core.h>

namespace visors::nav_app {
namespace {

// The same data set: t_oe as ephemeris_decoded.csv (1 us) and brdc.rnx write it; sets are 2 h apart.
constexpr double kSameToeS = 1e-3;

}  // namespace

core::Result<DecodedEphemerides> DecodedEphemerides::create(const gnss::EphemerisSet& screened,
                                                            std::span<const DecodedDataSet> decoded, const std::string& file) {
  DecodedEphemerides out;
  for (const DecodedDataSet& d : decoded) {
    if (d.prn < 1 || d.prn > gnss::kMaxGpsPrn) return core::Error{file, fmt::format("PRN {} is not 1..32", d.prn)};
    const gnss::ScreenedEphemeris* found = nullptr;
    for (const gnss::ScreenedEphemeris& s : screened.records()) {
      if (s.ephemeris.prn == d.prn && std::abs(s.ephemeris.toe.seconds_since(d.toe)) < kSameToeS) found = &s;
    }
    if (found == nullptr) {
      return core::Error{file, fmt::format("G{:02d} t_oe {} is not a record of brdc.rnx (files of different runs?)", d.prn,
                                           d.toe.format(core::TimeScale::kGps, 0))};
    }
    if (found->status != gnss::RecordStatus::kUsable) continue;
    out.by_prn_[static_cast<std::size_t>(d.prn)].push_back({found->ephemeris, d.decoded});
  }
  for (auto& entries : out.by_prn_) {  // t_oe order, as the screened set's (ties: the later transmission last)
    std::stable_sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) {
      return a.record.toe != b.record.toe ? a.record.toe < b.record.toe : a.record.transmission < b.record.transmission;
    });
  }
  return out;
}

const gnss::BroadcastEphemeris* DecodedEphemerides::select(int prn, core::GpsTime t) const {
  if (prn < 1 || prn > gnss::kMaxGpsPrn) return nullptr;
  const gnss::BroadcastEphemeris* best = nullptr;
  double best_distance = 0.0;
  for (const Entry& e : by_prn_[static_cast<std::size_t>(prn)]) {
    if (e.decoded > t) continue;
    const double distance = std::abs(t.seconds_since(e.record.toe));
    if (best == nullptr || distance <= best_distance) {  // sorted: on a tie the later transmission wins
      best = &e.record;
      best_distance = distance;
    }
  }
  return best != nullptr && gnss::within_fit_interval(*best, t) ? best : nullptr;
}

}  // namespace visors::nav_app
