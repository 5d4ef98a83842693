#include "visors/gnss/gps_measurement.hpp"

#include <cmath>
#include <string>

#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

core::Status validate(const GpsMeasurementEpoch& epoch) {
  using core::Problem;
  if (epoch.channel_count < 0 || epoch.channel_count > kMaxGpsChannels) return {Problem::kOutOfRange, "channel_count"};
  for (int k = 0; k < epoch.channel_count; ++k) {
    const GpsChannelMeasurement& c = epoch.channels[static_cast<std::size_t>(k)];
    if (c.prn < 1 || c.prn > kMaxGpsPrn) return {Problem::kOutOfRange, "channels.prn"};
    for (int j = 0; j < k; ++j) {
      if (epoch.channels[static_cast<std::size_t>(j)].prn == c.prn) return {Problem::kRepeated, "channels.prn"};
    }
    if (!(c.pseudorange_m >= 1e7 && c.pseudorange_m <= 5e7)) return {Problem::kOutOfRange, "channels.pseudorange_m"};
    if (!std::isfinite(c.carrier_phase_cycles)) return {Problem::kNotFinite, "channels.carrier_phase_cycles"};
    if (!std::isfinite(c.doppler_hz)) return {Problem::kNotFinite, "channels.doppler_hz"};
    if (!(c.cn0_dbhz >= 0.0 && c.cn0_dbhz <= 70.0)) return {Problem::kOutOfRange, "channels.cn0_dbhz"};
    if (!(c.lock_time_s >= 0.0)) return {Problem::kOutOfRange, "channels.lock_time_s"};
  }
  return {};
}

}  // namespace visors::gnss
