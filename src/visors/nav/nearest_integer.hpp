#pragma once
// Nearest integer of a double, inlined: std::round is an out-of-line libm call on baseline x86-64
// (no SSE4.1 roundsd), and the search rounds at every step. Adding and
// subtracting 1.5 x 2^52 leaves the nearest integer (ties to even) for |x| < 2^51, exactly; larger
// magnitudes are already integers in double precision or go to std::round.

#include <cmath>

namespace visors::nav {

inline double nearest_integer(double x) {
  constexpr double kShift = 6755399441055744.0;  // 1.5 x 2^52
  constexpr double kLimit = 2251799813685248.0;  // 2^51
  if (!(std::abs(x) < kLimit)) return std::round(x);
  // Not folded away: without -ffast-math the compiler keeps IEEE addition (SSE2, no excess precision).
  return (x + kShift) - kShift;
}

}  // namespace visors::nav
