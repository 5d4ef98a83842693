#include "visors/core/angles.hpp"

#include <cmath>

#include "visors/core/constants.hpp"

namespace visors::core {

double wrap_two_pi(double angle) {
  double w = std::fmod(angle, kTwoPi);
  if (w < 0.0) w += kTwoPi;
  return w >= kTwoPi ? 0.0 : w;  // fmod can round a tiny negative up to exactly 2 pi
}

double wrap_pi(double angle) {
  double w = std::fmod(angle + kPi, kTwoPi);
  if (w <= 0.0) w += kTwoPi;
  return w - kPi;
}

}  // namespace visors::core
