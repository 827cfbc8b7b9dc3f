#pragma once
// UTF-8 text as Unicode code points, strictly: text drawn by the arm comes from users' command
// lines and files, and malformed bytes must be an error, not a guess.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace animkit {

/// The code points of `text`; nothing when the bytes are not well-formed UTF-8 (RFC 3629: no
/// overlong forms, no surrogates, nothing above U+10FFFF, no sequence cut short).
std::optional<std::vector<char32_t>> decode_utf8(std::string_view text);

/// The UTF-8 bytes of code points (each must be a Unicode scalar value); decode_utf8's inverse.
std::string encode_utf8(const std::vector<char32_t>& code_points);

}  // namespace animkit
