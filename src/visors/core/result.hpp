#pragma once
// Result type for validation at API boundaries: flight code never throws across its API; a
// function that can reject its input returns Result<T> carrying either the value or an Error
// that names the offending field and the problem.

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace visors::core {

struct Error {
  std::string field;    // the input that was rejected, e.g. "chief.e"
  std::string message;  // what is wrong with it, e.g. "must be in [0, 1)"

  [[nodiscard]] std::string describe() const {
    return field.empty() ? message : field + ": " + message;
  }
};

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}          // NOLINT(google-explicit-constructor)
  Result(Error error) : state_(std::move(error)) {}      // NOLINT(google-explicit-constructor)

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
  [[nodiscard]] const Error& error() const {
    assert(!ok());
    return std::get<Error>(state_);
  }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }

 private:
  std::variant<T, Error> state_;
};

}  // namespace visors::core
