#include "visors/nav/gps_observations.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace visors::nav {

const GpsObservation* GpsReceiverEpoch::find(int prn) const {
  for (int i = 0; i < count; ++i) {
    if (observations[static_cast<std::size_t>(i)].prn == prn) return &observations[static_cast<std::size_t>(i)];
  }
  return nullptr;
}

core::Status check(const GpsReceiverEpoch& epoch) {
  if (epoch.count < 0 || epoch.count > kGpsSlots) return {core::Problem::kOutOfRange, "count"};
  for (int i = 0; i < epoch.count; ++i) {
    const int prn = epoch.observations[static_cast<std::size_t>(i)].prn;
    if (prn < 1 || prn > 32) return {core::Problem::kOutOfRange, "observations.prn"};
    for (int j = 0; j < i; ++j) {
      if (epoch.observations[static_cast<std::size_t>(j)].prn == prn) return {core::Problem::kRepeated, "observations.prn"};
    }
  }
  return {};
}

bool plausible(const GpsObservation& o) {
  constexpr double kMinCode = 1.5e7, kMaxCode = 3.5e7;  // [m]
  return o.code_m >= kMinCode && o.code_m <= kMaxCode && std::isfinite(o.phase_cycles);
}

static_assert(gnss::kMaxGpsChannels <= kGpsSlots, "an epoch holds every receiver channel");

GpsReceiverEpoch receiver_epoch(const gnss::GpsMeasurementEpoch& measurement) {
  GpsReceiverEpoch epoch;
  epoch.t = measurement.t;
  epoch.count = std::clamp(measurement.channel_count, 0, gnss::kMaxGpsChannels);
  for (int k = 0; k < epoch.count; ++k) {
    const gnss::GpsChannelMeasurement& m = measurement.channels[static_cast<std::size_t>(k)];
    GpsObservation& o = epoch.observations[static_cast<std::size_t>(k)];
    o.prn = m.prn;
    o.code_m = m.pseudorange_m;
    o.phase_cycles = m.carrier_phase_cycles;
    o.loss_of_lock = m.loss_of_lock;
    o.half_cycle = m.half_cycle_ambiguity;
  }
  return epoch;
}

}  // namespace visors::nav
