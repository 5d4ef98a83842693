#include "visors/core/check.hpp"

namespace visors::core {

std::string_view describe(Problem problem) {
  switch (problem) {
    case Problem::kNone: return "ok";
    case Problem::kNotFinite: return "must be finite";
    case Problem::kOutOfRange: return "out of range";
    case Problem::kTooOld: return "time tag is too old";
    case Problem::kInTheFuture: return "time tag is in the future";
    case Problem::kNotUnit: return "must be a unit quaternion";
    case Problem::kNotSymmetric: return "must be symmetric";
    case Problem::kRepeated: return "repeats an earlier one";
    case Problem::kInconsistent: return "disagrees with another field of the message";
    case Problem::kUnknown: return "names nothing known";
  }
  return "unknown problem";
}

}  // namespace visors::core
