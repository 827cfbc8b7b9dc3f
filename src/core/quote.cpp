#include "animkit/core/quote.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

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

// What the input character at raw[i] shows as: the text, how many bytes of raw it stands for,
// and how many characters it counts as (an escape such as \x7f counts its four, a UTF-8
// character one), so escaping cannot make a message longer than its budget.
struct ShownCharacter {
  std::string text;
  std::size_t consumed = 1;
  std::size_t shown = 0;
};

ShownCharacter shown_character(std::string_view raw, std::size_t i) {
  const auto c = static_cast<std::uint8_t>(raw[i]);
  ShownCharacter character;
  bool kept_character = false;  // a multi-byte UTF-8 character shown as itself
  if (c >= 0x20 && c < 0x7F) {
    character.text = static_cast<char>(c);
  } else if (c == '\n') {
    character.text = "\\n";
  } else if (c == '\r') {
    character.text = "\\r";
  } else if (c == '\t') {
    character.text = "\\t";
  } else if (const std::size_t n = c >= 0x80 ? utf8_sequence_length(raw, i) : 0; n > 0) {
    character.consumed = n;
    // A well-formed sequence is kept, except the C1 controls U+0080..U+009F (a terminal
    // may read U+009B as an escape introducer).
    if (c == 0xC2 && static_cast<std::uint8_t>(raw[i + 1]) < 0xA0) {
      char escaped[16];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<std::uint8_t>(raw[i + 1]));
      character.text = escaped;
    } else {
      character.text = raw.substr(i, n);
      kept_character = true;
    }
  } else {
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", c);
    character.text = escaped;
  }
  character.shown = kept_character ? 1 : character.text.size();
  return character;
}

// Appends raw[0..] made printable, at most max_chars characters as shown; true if all of it
// fit.
bool append_escaped(std::string& out, std::string_view raw, std::size_t max_chars) {
  std::size_t shown = 0;
  for (std::size_t i = 0; i < raw.size();) {
    const ShownCharacter character = shown_character(raw, i);
    shown += character.shown;
    if (shown > max_chars) return false;
    out += character.text;
    i += character.consumed;
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

std::string shown_path(std::string_view raw, std::size_t max_chars) {
  std::vector<ShownCharacter> characters;
  std::size_t shown = 0;
  for (std::size_t i = 0; i < raw.size(); i += characters.back().consumed) {
    characters.push_back(shown_character(raw, i));
    shown += characters.back().shown;
  }
  const auto joined = [&](std::size_t begin, std::size_t end) {
    std::string out;
    for (std::size_t k = begin; k < end; ++k) out += characters[k].text;
    return out;
  };
  if (shown <= max_chars) return joined(0, characters.size());
  // The start says where, the end names the file: both are kept around "...".
  const std::size_t head_budget = max_chars / 3;
  const std::size_t tail_budget = max_chars - head_budget - std::min<std::size_t>(3, max_chars);
  std::size_t head = 0, head_shown = 0;
  while (head_shown + characters[head].shown <= head_budget) head_shown += characters[head++].shown;
  std::size_t tail = characters.size(), tail_shown = 0;
  while (tail > head && tail_shown + characters[tail - 1].shown <= tail_budget)
    tail_shown += characters[--tail].shown;
  return joined(0, head) + "..." + joined(tail, characters.size());
}

}  // namespace animkit
