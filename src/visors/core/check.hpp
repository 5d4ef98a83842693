#pragma once
// The verdict of a check a flight step makes on its input, without allocating: ok, or the problem
// as a code and the offending field's name, a string literal (static storage). What the channel
// messages' validation returns (gnc/messages.hpp validate, and the GPS epochs' checks it calls),
// so that refusing a record costs no heap allocation, every step of a garbage burst included.
// Creation-time validation keeps core::Error (core/status.hpp), whose text may be composed.

#include <cstdint>
#include <string>
#include <string_view>

#include "visors/core/status.hpp"

namespace visors::core {

enum class Problem : std::uint8_t {
  kNone,
  kNotFinite,     // NaN or infinite
  kOutOfRange,    // outside its valid interval
  kTooOld,        // a time tag older than its channel allows
  kInTheFuture,   // a time tag after the step's time
  kNotUnit,       // a quaternion whose norm is not 1
  kNotSymmetric,  // a covariance that is not symmetric
  kRepeated,      // a PRN that repeats an earlier one
  kInconsistent,  // disagrees with another field of the message
  kUnknown,       // an enumerated value that names nothing
};

/// What a problem means, for an error message.
std::string_view describe(Problem problem);

class [[nodiscard]] Check {
 public:
  constexpr Check() = default;  // ok
  constexpr Check(Problem problem, const char* field) : problem_(problem), field_(field) {}

  [[nodiscard]] constexpr bool ok() const { return problem_ == Problem::kNone; }
  constexpr explicit operator bool() const { return ok(); }
  [[nodiscard]] constexpr Problem problem() const { return problem_; }
  /// The field's name ("" when ok): a string literal, e.g. "navigation.chief_gcrf".
  [[nodiscard]] constexpr const char* field() const { return field_; }
  /// As an Error, for ground callers (this allocates).
  [[nodiscard]] Error error() const { return Error{field_, std::string(describe(problem_))}; }

 private:
  Problem problem_ = Problem::kNone;
  const char* field_ = "";
};

}  // namespace visors::core
