#include "visors/core/status.hpp"

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
    case Problem::kSingular: return "singular geometry: no unique solution";
    case Problem::kNotConverged: return "did not converge";
    case Problem::kInfeasible: return "no feasible solution";
    case Problem::kCapacity: return "exceeds the preallocated capacity";
    case Problem::kNotReady: return "called before its inputs were given";
  }
  return "unknown problem";
}

std::string Status::path() const {
  std::string joined;
  for (const char* scope : scopes_) {
    if (scope == nullptr || *scope == '\0') continue;
    if (!joined.empty()) joined += '.';
    joined += scope;
  }
  if (*field_ != '\0') {
    if (!joined.empty()) joined += '.';
    joined += field_;
  }
  return joined;
}

}  // namespace visors::core
