#pragma once
// animkit's errors as Python exceptions: every Result<T> and validate() that fails at the
// binding boundary raises animkit.Error (a ValueError) with the library's message, so a
// script gets the same words the CLI prints, and bad input never reaches an assert.
#include <pybind11/pybind11.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "animkit/core/result.h"

namespace animkit::python {

/// Thrown by the bindings; pybind11 turns it into animkit.Error (register_errors).
class BindingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Registers animkit.Error on the module (once, from module.cpp).
void register_errors(pybind11::module_& m);

[[noreturn]] inline void raise(const Error& error) {
  throw BindingError(error.message);
}
[[noreturn]] inline void raise(std::string message) {
  throw BindingError(std::move(message));
}

/// The value of a Result, or animkit.Error with its message.
template <class T>
T unwrap(Result<T>&& result) {
  if (!result) raise(result.error());
  return std::move(*result);
}
inline void unwrap(Result<void>&& result) {
  if (!result) raise(result.error());
}

/// Raises the error a validate() found, if any.
inline void check(const std::optional<Error>& problem) {
  if (problem) raise(*problem);
}

}  // namespace animkit::python
