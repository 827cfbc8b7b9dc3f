#pragma once
// Text as pen strokes, from a TrueType/OpenType font through FreeType: each glyph contour's
// lines and quadratic/cubic Bezier arcs flattened to a tolerance (one closed stroke per
// contour), or, for a single line per pen stroke, each glyph's centre line (the skeleton of
// the rendered glyph, as for images).
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// DejaVu Sans from Debian's fonts-dejavu-core.
inline const std::filesystem::path kDefaultFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

/// How text becomes strokes: the font, the flattening tolerance and outline or centre line.
struct TextOptions {
  std::filesystem::path font = kDefaultFont;  ///< a TrueType/OpenType font file
  /// Largest distance between a curve and its flattened polyline, as a fraction of the em
  /// (the font's size). In (0, 0.1].
  double tolerance = 0.002;
  /// Draw each glyph's centre line instead of its outline.
  bool centerline = false;

  /// The first out-of-range option (a tolerance outside (0, 0.1]), or nothing. The font file is
  /// not checked here.
  std::optional<Error> validate() const;
};

/// Largest font file read (CJK collections are tens of megabytes).
constexpr std::uintmax_t kMaxFontFileBytes = 256u << 20;

/// The strokes of `utf8` set in one line per '\n', in font units scaled to an em of 1
/// (x right, y up, the baseline of the first line at y = 0). Errors: empty text, invalid
/// UTF-8, a missing, unreadable or non-font file (naming the file: "font /tmp: is a folder,
/// not a file"), a character the font lacks, text with nothing visible (spaces only).
Result<Strokes> text_strokes(std::string_view utf8, const TextOptions& options = {});

/// text_strokes with the font's bytes in memory (`options.font` is not read); `font_name`
/// names the font in errors.
Result<Strokes> text_strokes_from_font_data(std::string_view utf8,
                                            std::span<const std::byte> font_data,
                                            std::string_view font_name,
                                            const TextOptions& options = {});

}  // namespace animkit
