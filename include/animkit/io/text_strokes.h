#pragma once
// Text as pen strokes, from a TrueType/OpenType font through FreeType: each glyph contour's
// lines and quadratic/cubic Bezier arcs flattened to a tolerance (one closed stroke per
// contour), or, for a single line per pen stroke, each glyph's centre line (the skeleton of
// the rendered glyph, as for images).
#include <filesystem>
#include <string_view>

#include "animkit/core/result.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// DejaVu Sans from Debian's fonts-dejavu-core.
inline const std::filesystem::path kDefaultFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct TextOptions {
  std::filesystem::path font = kDefaultFont;
  /// Largest distance between a curve and its flattened polyline, as a fraction of the em
  /// (the font's size). In (0, 0.1].
  double tolerance = 0.002;
  /// Draw each glyph's centre line instead of its outline.
  bool centerline = false;

  std::optional<Error> validate() const;
};

/// The strokes of `utf8` set in one line per '\n', in font units scaled to an em of 1
/// (x right, y up, the baseline of the first line at y = 0). Errors: empty text, invalid
/// UTF-8, a missing or unreadable font (naming the file), a character the font lacks, text
/// with nothing visible (spaces only).
Result<Strokes> text_strokes(std::string_view utf8, const TextOptions& options = {});

}  // namespace animkit
