#include "xml_text.h"

#include "animkit/core/utf8.h"

namespace animkit {

// Text for XML character data and attribute values: the five markup characters as entities,
// and what XML 1.0 forbids (control characters, bytes that are not UTF-8) as U+FFFD, so a
// drawing named "a&b<c>.csv" or holding any bytes still makes a well-formed SVG.
std::string xml_text(std::string_view raw) {
  std::string out;
  for (std::size_t i = 0; i < raw.size();) {
    const char c = raw[i];
    const auto byte = static_cast<unsigned char>(c);
    if (byte >= 0x80) {
      // A whole well-formed sequence is copied as it is (decode_utf8 judges it).
      const std::size_t length = byte >= 0xF0 ? 4 : byte >= 0xE0 ? 3 : 2;
      const std::string_view sequence = raw.substr(i, length);
      const auto decoded = decode_utf8(sequence);
      const bool ok = sequence.size() == length && decoded && decoded->size() == 1 &&
                      (*decoded)[0] != 0xFFFE && (*decoded)[0] != 0xFFFF;
      out += ok ? std::string(sequence) : "\xEF\xBF\xBD";
      i += ok ? length : 1;
      continue;
    }
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += byte < 0x20 && c != '\t' && c != '\n' ? "\xEF\xBF\xBD" : std::string(1, c);
    }
    ++i;
  }
  return out;
}

}  // namespace animkit
