#include "visors/sim/host_clock.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace visors::sim {

core::Result<bool> HostClockSettings::validate() const {
  if (!std::isfinite(pps_sigma_s) || pps_sigma_s < 0.0 || pps_sigma_s > 1e-3) {
    return core::Error{"pps_sigma_ns", "must be finite, in [0, 1e6] ns"};
  }
  if (!std::isfinite(oscillator_sigma) || oscillator_sigma < 0.0 || oscillator_sigma > 1e-3) {
    return core::Error{"oscillator_sigma_ppm", "must be finite, in [0, 1000] ppm"};
  }
  return true;
}

HostClock::HostClock(const HostClockSettings& settings, RandomStream rng) : settings_(settings), rng_(std::move(rng)) {
  frequency_error_ = rng_.normal(settings_.oscillator_sigma);
}

core::Result<HostClock> HostClock::create(const HostClockSettings& settings, RandomStream rng) {
  if (auto ok = settings.validate(); !ok) return ok.error();
  return HostClock(settings, std::move(rng));
}

void HostClock::tone(double t_s, bool receiver_solution) {
  if (receiver_solution) {
    offset_s_ = rng_.normal(settings_.pps_sigma_s);
  } else if (started_) {
    offset_s_ += frequency_error_ * (t_s - last_t_s_);
  }
  last_t_s_ = t_s;
  started_ = true;
  max_abs_offset_s_ = std::max(max_abs_offset_s_, std::abs(offset_s_));
}

}  // namespace visors::sim
