#pragma once
// What a fuzz target checks besides memory safety: a broken promise stops the run like a crash
// (abort), with the promise printed, so libFuzzer keeps the input that broke it.
#include <cstdio>
#include <cstdlib>
#include <string_view>

#include "animkit/core/utf8.h"

namespace animkit::fuzz {

inline void check(bool ok, const char* promise) {
  if (!ok) {
    std::fprintf(stderr, "fuzz check failed: %s\n", promise);
    std::abort();
  }
}

/// Error messages stay one short line of well-formed UTF-8 whatever the input held.
inline void check_message(std::string_view message, std::string_view starts_with) {
  // 80 quoted characters of up to 6 bytes each (\u0085) plus the words around them.
  check(!message.empty() && message.size() < 800, "an error message is 1..799 bytes");
  check(message.starts_with(starts_with), "an error message starts with the input's name");
  check(message.find_first_of("\n\r\x1b") == std::string_view::npos,
        "an error message has no newline or escape");
  check(decode_utf8(message).has_value(), "an error message is UTF-8");
}

}  // namespace animkit::fuzz
