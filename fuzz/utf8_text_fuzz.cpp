// Fuzzes text as users type it: the strict UTF-8 decoder, quoting raw input into error
// messages, and short texts drawn with the default font (DejaVu Sans, read once).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "animkit/core/quote.h"
#include "animkit/core/utf8.h"
#include "animkit/io/file_bytes.h"
#include "animkit/io/text_strokes.h"
#include "fuzz_check.h"

namespace {

using animkit::fuzz::check;

// Quoted or sanitized input is one line of well-formed UTF-8 without control characters.
void check_printable(std::string_view shown, std::size_t max_bytes) {
  check(shown.size() <= max_bytes, "quoted input is cut short");
  check(animkit::decode_utf8(shown).has_value(), "quoted input is UTF-8");
  for (const char c : shown) {
    const auto byte = static_cast<unsigned char>(c);
    check(byte >= 0x20 && byte != 0x7F, "quoted input has no control character");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto code_points = animkit::decode_utf8(text);
  if (code_points) {
    check(animkit::encode_utf8(*code_points) == text, "decoding then encoding gives the bytes");
  }
  // 80 characters of at most 6 bytes each (\u0085), the quotes and the cut's note.
  check_printable(animkit::quote_input(text), 2 + 80 * 6 + 40);
  check_printable(animkit::sanitize_message(text, 100), 100 * 6 + 20);

  if (!code_points || code_points->size() > 4) return 0;  // drawing is slow: short texts only
  static const auto font = animkit::read_file_bytes(animkit::kDefaultFont, 64u << 20);
  check(font.has_value(), "the default font is installed");
  animkit::TextOptions options;
  options.centerline = code_points->size() <= 2 && size % 2 == 1;
  const auto strokes = animkit::text_strokes_from_font_data(text, std::as_bytes(std::span(*font)),
                                                            "DejaVuSans.ttf", options);
  if (strokes) {
    for (const animkit::Stroke& stroke : *strokes)
      check(stroke.size() >= 2, "strokes have 2 points");
  } else {
    animkit::fuzz::check_message(strokes.error().message, "");
  }
  return 0;
}
