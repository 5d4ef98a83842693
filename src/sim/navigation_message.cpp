#include "sim/navigation_message.hpp"

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

}  // namespace visors::sim
