// Fuzzes fonts as `animkit ik --font FILE --text ...` reads them: FreeType parsing the bytes,
// then glyph outlines flattened into strokes or rendered for their centre lines.
//
// Input layout: byte 0 = options (bit 0: centre lines; bits 1-2: flattening tolerance), byte 1
// = the text's length n (mod 8), then n bytes of UTF-8 text, then the font file.
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "animkit/io/text_strokes.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  const std::size_t text_size = std::min<std::size_t>(data[1] % 8, size - 2);
  const std::string_view text(reinterpret_cast<const char*>(data + 2), text_size);
  const auto font = std::as_bytes(std::span(data + 2 + text_size, size - 2 - text_size));
  animkit::TextOptions options;
  options.centerline = (data[0] & 1) != 0;
  constexpr double kTolerances[] = {0.002, 0.0005, 0.02, 0.1};
  options.tolerance = kTolerances[(data[0] >> 1) & 3];
  const auto strokes = animkit::text_strokes_from_font_data(text, font, "fuzz.ttf", options);
  if (!strokes) {
    const std::string& message = strokes.error().message;
    const bool about_font = message.starts_with("font fuzz.ttf");
    animkit::fuzz::check_message(message, about_font ? "font fuzz.ttf" : "");
    return 0;
  }
  for (const animkit::Stroke& stroke : *strokes) {
    animkit::fuzz::check(stroke.size() >= 2, "a stroke has two points");
    for (const animkit::Point2& p : stroke) {
      animkit::fuzz::check(p.allFinite(), "stroke points are finite");
    }
  }
  return 0;
}
