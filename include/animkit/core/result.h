#pragma once
// Errors are values at the API boundary: a Result<T> holds either a T or an Error whose
// message names the problem in words a user can act on ("bone 3 has zero length").
#include <expected>
#include <string>

namespace animkit {

/// Why an operation failed: the error half of Result<T>.
struct Error {
  /// What went wrong, in words a user can act on ("bone 3 has zero length").
  std::string message;
};

/// Either a T or the Error that prevented computing it.
template <class T>
using Result = std::expected<T, Error>;

/// Shorthand for returning a failed Result: `return fail("bone 3 has zero length");`
inline std::unexpected<Error> fail(std::string message) {
  return std::unexpected<Error>(Error{std::move(message)});
}

}  // namespace animkit
