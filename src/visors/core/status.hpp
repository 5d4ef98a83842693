#pragma once
// The flight layers' one status type: ok, or a problem as a code, the offending input's name and
// what is wrong with it, every text a string literal (static storage), so that refusing an input
// or failing a plan costs no heap allocation in a flight step. What the channel messages'
// validation, the GPS epochs' checks, the planners' and the safety check's step-time calls, the
// orbit conversions they make and the flight settings' validators return: `Status`, or
// `Outcome<T>` when a value comes back.
// A caller that adds context does so with `within("chief_mean_t0")`, which prepends a scope
// (a literal too) instead of composing a string. `error()` turns either into a core::Error
// (core/result.hpp) for the ground and for a component's create(), whose texts may be composed:
// that conversion allocates.

#include <array>
#include <cassert>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

#include "visors/core/result.hpp"

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
  kSingular,      // a geometry or matrix that admits no (unique) solution
  kNotConverged,  // an iteration that did not meet its tolerance within its budget
  kInfeasible,    // no solution satisfies the constraints (no safe escape, no reachable target)
  kCapacity,      // more than the preallocated capacity holds
  kNotReady,      // called before what it needs was given (a target, an estimate)
};

/// What a problem means, for an error message without a detail.
std::string_view describe(Problem problem);

class [[nodiscard]] Status {
 public:
  static constexpr std::size_t kMaxScopes = 3;

  constexpr Status() = default;  // ok
  /// `field` and `detail` are string literals; an empty detail stands for describe(problem).
  constexpr Status(Problem problem, const char* field, const char* detail = "")
      : problem_(problem), field_(field), detail_(detail) {}

  [[nodiscard]] constexpr bool ok() const { return problem_ == Problem::kNone; }
  constexpr explicit operator bool() const { return ok(); }
  [[nodiscard]] constexpr Problem problem() const { return problem_; }
  /// The field's own name ("" when ok): a string literal, e.g. "chief_gcrf".
  [[nodiscard]] constexpr const char* field() const { return field_; }
  /// What is wrong with it: the detail given, else the problem's description.
  [[nodiscard]] std::string_view message() const { return *detail_ != '\0' ? std::string_view(detail_) : describe(problem_); }
  /// The enclosing inputs' names, outermost first (unused entries nullptr).
  [[nodiscard]] constexpr const std::array<const char*, kMaxScopes>& scopes() const { return scopes_; }

  /// The same status seen from an enclosing input: Status{.., "e"}.within("chief") names
  /// "chief.e". Up to kMaxScopes levels; beyond them the outermost are kept and the innermost
  /// scope dropped (debug builds assert).
  [[nodiscard]] constexpr Status within(const char* scope) const {
    if (ok()) return *this;
    Status s = *this;
    assert(s.scopes_.back() == nullptr && "core::Status: more nested scopes than kMaxScopes");
    for (std::size_t k = kMaxScopes - 1; k > 0; --k) s.scopes_[k] = s.scopes_[k - 1];
    s.scopes_[0] = scope;
    return s;
  }

  /// The same problem and detail, said of another field (a shared check reporting for its caller).
  [[nodiscard]] constexpr Status renamed(const char* field) const {
    Status s = *this;
    s.field_ = field;
    return s;
  }

  /// The full name, scopes and field joined by '.' (allocates: for the ground).
  [[nodiscard]] std::string path() const;
  /// As an Error, for ground callers and a component's create() (this allocates).
  [[nodiscard]] Error error() const { return Error{path(), std::string(message())}; }

 private:
  Problem problem_ = Problem::kNone;
  const char* field_ = "";
  const char* detail_ = "";
  std::array<const char*, kMaxScopes> scopes_{};
};

/// "must be in [Lo, Hi]" as text with static storage, written at compile time, for a Status
/// detail that names a range whose bounds are constants (in_range_text<1, kMaxWaypoints>()).
template <long long Lo, long long Hi>
struct InRangeText {
  static constexpr std::array<char, 64> kText = [] {
    std::array<char, 64> out{};
    std::size_t n = 0;
    const auto put = [&](const char* s) {
      while (*s != '\0') out[n++] = *s++;
    };
    const auto put_integer = [&](long long v) {
      if (v < 0) out[n++] = '-';
      unsigned long long u = v < 0 ? 0ULL - static_cast<unsigned long long>(v) : static_cast<unsigned long long>(v);
      std::array<char, 20> digits{};
      std::size_t k = 0;
      do {
        digits[k++] = static_cast<char>('0' + u % 10);
        u /= 10;
      } while (u != 0);
      while (k > 0) out[n++] = digits[--k];
    };
    put("must be in [");
    put_integer(Lo);
    put(", ");
    put_integer(Hi);
    put("]");
    return out;
  }();
};
template <long long Lo, long long Hi>
constexpr const char* in_range_text() {
  return InRangeText<Lo, Hi>::kText.data();
}

/// A value or the Status that refused to make it: Result's shape without an allocating error.
template <typename T>
class [[nodiscard]] Outcome {
 public:
  Outcome(T value) : state_(std::move(value)) {}  // NOLINT(google-explicit-constructor)
  Outcome(Status status) : state_(status) {       // NOLINT(google-explicit-constructor)
    assert(!status.ok() && "core::Outcome: a failure needs a problem");
  }

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }

  [[nodiscard]] const T& value() const& {
    assert(ok());
    return std::get<T>(state_);
  }
  [[nodiscard]] T&& value() && {
    assert(ok());
    return std::get<T>(std::move(state_));
  }
  /// ok (Status{}) or the failure.
  [[nodiscard]] Status status() const { return ok() ? Status{} : std::get<Status>(state_); }
  /// The failure as an Error (allocates: for the ground).
  [[nodiscard]] Error error() const {
    assert(!ok());
    return status().error();
  }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }

  /// For ground callers that return a Result: a failure's text is composed then (allocates).
  operator Result<T>() && {  // NOLINT(google-explicit-constructor)
    if (ok()) return Result<T>(std::get<T>(std::move(state_)));
    return Result<T>(error());
  }

 private:
  std::variant<T, Status> state_;
};

}  // namespace visors::core
