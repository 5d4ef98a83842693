#include "visors/sim/navigation_message.hpp"

#include <algorithm>
#include <cmath>

namespace visors::sim {
namespace {

constexpr double kFrameS = 30.0;
constexpr double kSubframeS = 6.0;

}  // namespace

double ephemeris_decoded_at(double from_gps_s) {
  double ready = from_gps_s;
  for (int j = 0; j < 3; ++j) {
    const double offset = kSubframeS * j;  // subframe j + 1 starts at 30 k + 6 j
    const double start = kFrameS * std::ceil((from_gps_s - offset) / kFrameS) + offset;
    ready = std::max(ready, start + kSubframeS);
  }
  return ready;
}

DataSetsByPrn data_sets_by_prn(std::span<const gnss::BroadcastEphemeris> records) {
  DataSetsByPrn sets;
  for (std::size_t i = 0; i < records.size(); ++i) {
    if (records[i].prn >= 1 && records[i].prn <= gnss::kMaxGpsPrn) sets[static_cast<std::size_t>(records[i].prn)].push_back(i);
  }
  return sets;
}

std::optional<std::size_t> newly_decoded_data_set(std::span<const gnss::BroadcastEphemeris> records,
                                                  std::span<const std::size_t> sets, core::GpsTime t,
                                                  double half_refresh_s, double lock_time_s, std::size_t next) {
  if (sets.empty()) return std::nullopt;
  // The set in force: from the last one passed on (a set replaced is never in force again).
  std::size_t current = next > 0 ? next - 1 : 0;
  while (current + 1 < sets.size() && half_refresh_s > 0.0 && t.seconds_since(records[sets[current + 1]].toe) >= -half_refresh_s) {
    ++current;
  }
  if (next > current) return std::nullopt;
  const double lock_start_s = t.seconds() - lock_time_s;
  const double broadcast_from_s = current == 0 ? lock_start_s : records[sets[current]].toe.seconds() - half_refresh_s;
  if (t.seconds() < ephemeris_decoded_at(std::max(lock_start_s, broadcast_from_s))) return std::nullopt;
  return current;
}

}  // namespace visors::sim
