#pragma once
// Result<T>: a value, or the message of what went wrong. Host code returns it across module boundaries instead of
// throwing; the message names the place and the problem, ready for a user.

#include <string>
#include <utility>
#include <variant>

namespace duet {

struct Failure {
  std::string message;
};

template <typename T>
class [[nodiscard]] Result {
 public:
  Result(T value) : state_(std::move(value)) {}  // NOLINT(google-explicit-constructor): returning a value is success
  Result(Failure failure) : state_(std::move(failure)) {}  // NOLINT(google-explicit-constructor)

  [[nodiscard]] bool ok() const { return std::holds_alternative<T>(state_); }
  explicit operator bool() const { return ok(); }
  // Precondition for value(): ok(); for error(): !ok().
  [[nodiscard]] T& value() & { return std::get<T>(state_); }
  [[nodiscard]] const T& value() const& { return std::get<T>(state_); }
  [[nodiscard]] T&& value() && { return std::get<T>(std::move(state_)); }
  [[nodiscard]] const std::string& error() const { return std::get<Failure>(state_).message; }

 private:
  std::variant<T, Failure> state_;
};

struct Done {};  // the value of a Result that only says whether it worked
using Status = Result<Done>;
inline Status done() { return Done{}; }

}  // namespace duet
