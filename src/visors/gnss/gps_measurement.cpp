#include "visors/gnss/gps_measurement.hpp"

#include <cmath>
#include <string>

#include "visors/gnss/gps_constants.hpp"

namespace visors::gnss {

core::Result<bool> validate(const GpsMeasurementEpoch& epoch) {
  if (epoch.channel_count < 0 || epoch.channel_count > kMaxGpsChannels) {
    return core::Error{"channel_count", "must be in 0..12, got " + std::to_string(epoch.channel_count)};
  }
  for (int k = 0; k < epoch.channel_count; ++k) {
    const GpsChannelMeasurement& c = epoch.channels[static_cast<std::size_t>(k)];
    const std::string name = "channels[" + std::to_string(k) + "]";
    if (c.prn < 1 || c.prn > kMaxGpsPrn) return core::Error{name + ".prn", "must be in 1..32"};
    for (int j = 0; j < k; ++j) {
      if (epoch.channels[static_cast<std::size_t>(j)].prn == c.prn) return core::Error{name + ".prn", "repeats another channel's PRN"};
    }
    if (!(c.pseudorange_m >= 1e7 && c.pseudorange_m <= 5e7)) return core::Error{name + ".pseudorange_m", "must be in [1e7, 5e7] m"};
    if (!std::isfinite(c.carrier_phase_cycles)) return core::Error{name + ".carrier_phase_cycles", "must be finite"};
    if (!std::isfinite(c.doppler_hz)) return core::Error{name + ".doppler_hz", "must be finite"};
    if (!(c.cn0_dbhz >= 0.0 && c.cn0_dbhz <= 70.0)) return core::Error{name + ".cn0_dbhz", "must be in [0, 70] dB-Hz"};
    if (!(c.lock_time_s >= 0.0)) return core::Error{name + ".lock_time_s", "must be >= 0"};
  }
  return true;
}

}  // namespace visors::gnss
