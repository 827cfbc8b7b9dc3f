#pragma once
// Internal to the BVH reader: its lines and tokens, number parsing, and the HIERARCHY part
// (bvh_hierarchy.cpp), which bvh_reader.cpp calls before reading MOTION.
#include <charconv>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/io/bvh.h"
#include "text_lines.h"

namespace animkit::bvh_detail {

inline constexpr std::string_view kSpaces = kTokenSpaces;

/// What a joint name cannot hold and still be written and read back as one name: whitespace,
/// braces and '#'.
inline constexpr std::string_view kNotInNames = " \t\r\n\v\f{}#";

/// A line that is neither blank nor a '#' comment.
struct Line {
  std::string_view text;
  int number;  // 1-based
};

struct Token {
  std::string_view text;
  int line;
};

enum class Number { ok, malformed, not_finite };

// All of `token` as a decimal number ("1e-3", "+2", ".5", "nan" and "inf" read as not finite).
inline Number parse_number(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  if (ptr != end || token.empty()) return Number::malformed;
  if (ec == std::errc::result_out_of_range || !std::isfinite(value)) return Number::not_finite;
  return ec == std::errc() ? Number::ok : Number::malformed;
}

inline bool parse_count(std::string_view token, long max, long& value) {
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return !token.empty() && ptr == end && ec == std::errc() && value >= 0 && value <= max;
}

inline bool parse_channel(std::string_view token, BvhChannel& channel) {
  for (int c = 0; c < 6; ++c) {
    if (token == bvh_channel_name(static_cast<BvhChannel>(c))) {
      channel = static_cast<BvhChannel>(c);
      return true;
    }
  }
  return false;
}

/// A joint name as messages show it: bytes that are not printable UTF-8 escaped, cut after 32
/// characters, so a message holding a name and a quoted value stays one short line.
inline std::string shown_name(std::string_view name) {
  return sanitize_message(name, 32);
}

/// "NAME: line N: message", made safe to print (control bytes escaped, length capped).
inline Error error_at(const std::string& file, int line, const std::string& message) {
  return Error{sanitize_message(file + ": line " + std::to_string(line) + ": " + message)};
}

/// Reads the joints, offsets and channels of the lines before MOTION into `clip`, and sets
/// `motion_line` to the index in `lines` of the MOTION line. `lines` is not empty.
std::optional<Error> read_bvh_hierarchy(std::span<const Line> lines, const std::string& file,
                                        double scale, BvhClip& clip, std::size_t& motion_line);

}  // namespace animkit::bvh_detail
