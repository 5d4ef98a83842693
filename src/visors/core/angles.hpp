#pragma once
// Angle helpers [rad].

namespace visors::core {

/// Wraps to [0, 2 pi).
double wrap_two_pi(double angle);

/// Wraps to (-pi, pi], the convention of the ROE's dlambda (docs/conventions.md).
double wrap_pi(double angle);

}  // namespace visors::core
