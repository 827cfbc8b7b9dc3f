#include "animkit/core/quote.h"

#include <cstdint>
#include <cstdio>

namespace animkit {

namespace {

// Length of the well-formed UTF-8 sequence starting at text[i] (RFC 3629: no overlongs, no
// surrogates, nothing above U+10FFFF), or 0 if it is not one. Only multi-byte sequences are
// asked about here.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<std::uint8_t>(text[k]); };
  const std::uint8_t lead = byte(i);
  std::size_t length = 0;
  std::uint8_t low = 0x80, high = 0xBF;  // allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    if (lead == 0xE0) low = 0xA0;
    if (lead == 0xED) high = 0x9F;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    if (lead == 0xF0) low = 0x90;
    if (lead == 0xF4) high = 0x8F;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (byte(i + 1) < low || byte(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

// Appends raw[0..] made printable, at most max_chars characters as shown (an escape such as
// \x7f counts its four, a UTF-8 character one), so escaping cannot make a message longer than
// its budget; true if all of it fit.
bool append_escaped(std::string& out, std::string_view raw, std::size_t max_chars) {
  std::size_t shown = 0;
  for (std::size_t i = 0; i < raw.size();) {
    const auto c = static_cast<std::uint8_t>(raw[i]);
    std::string piece;  // what raw[i..] shows as
    std::size_t consumed = 1;
    bool kept_character = false;  // a multi-byte UTF-8 character shown as itself
    if (c >= 0x20 && c < 0x7F) {
      piece = static_cast<char>(c);
    } else if (c == '\n') {
      piece = "\\n";
    } else if (c == '\r') {
      piece = "\\r";
    } else if (c == '\t') {
      piece = "\\t";
    } else if (const std::size_t n = c >= 0x80 ? utf8_sequence_length(raw, i) : 0; n > 0) {
      consumed = n;
      // A well-formed sequence is kept, except the C1 controls U+0080..U+009F (a terminal
      // may read U+009B as an escape introducer).
      if (c == 0xC2 && static_cast<std::uint8_t>(raw[i + 1]) < 0xA0) {
        char escaped[16];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<std::uint8_t>(raw[i + 1]));
        piece = escaped;
      } else {
        piece = raw.substr(i, n);
        kept_character = true;
      }
    } else {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
      piece = escaped;
    }
    shown += kept_character ? 1 : piece.size();
    if (shown > max_chars) return false;
    out += piece;
    i += consumed;
  }
  return true;
}

}  // namespace

std::string quote_input(std::string_view raw, std::size_t max_chars) {
  std::string out = "'";
  if (append_escaped(out, raw, max_chars)) return out + "'";
  return out + "...' (" + std::to_string(raw.size()) + " bytes)";
}

std::string sanitize_message(std::string_view raw, std::size_t max_chars) {
  std::string out;
  if (!append_escaped(out, raw, max_chars)) out += "... (cut)";
  return out;
}

}  // namespace animkit
