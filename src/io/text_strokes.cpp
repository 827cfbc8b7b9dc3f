#include "animkit/io/text_strokes.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "animkit/core/utf8.h"
#include "animkit/core/validation.h"
#include "animkit/io/file_bytes.h"
#include "animkit/trajectory/image_strokes.h"

namespace animkit {

namespace {

std::string code_point_name(char32_t c) {
  char text[16];
  std::snprintf(text, sizeof text, "U+%04X", static_cast<unsigned>(c));
  return text;
}

struct Library {
  FT_Library handle = nullptr;
  ~Library() {
    if (face) FT_Done_Face(face);
    if (handle) FT_Done_FreeType(handle);
  }
  FT_Face face = nullptr;
};

// Collects a glyph outline as polylines, flattening Bezier arcs (FreeType's decomposition
// callbacks: move, line, conic = quadratic, cubic).
struct Flattener {
  Strokes strokes;
  Point2 offset;     // where the glyph's origin sits (font units)
  double tolerance;  // font units
  Point2 current;

  Point2 point(const FT_Vector* v) const {
    return offset + Point2(static_cast<double>(v->x), static_cast<double>(v->y));
  }
  void quadratic(const Point2& p0, const Point2& p1, const Point2& p2, int depth) {
    // Flat when the control point is within the tolerance of the chord's midpoint region.
    if (depth > 16 || (p1 - 0.5 * (p0 + p2)).norm() <= 2.0 * tolerance) {
      strokes.back().push_back(p2);
      return;
    }
    const Point2 a = 0.5 * (p0 + p1), b = 0.5 * (p1 + p2), m = 0.5 * (a + b);
    quadratic(p0, a, m, depth + 1);
    quadratic(m, b, p2, depth + 1);
  }
  void cubic(const Point2& p0, const Point2& p1, const Point2& p2, const Point2& p3, int depth) {
    const double d1 = (p1 - (2.0 * p0 + p3) / 3.0).norm(), d2 = (p2 - (p0 + 2.0 * p3) / 3.0).norm();
    if (depth > 16 || std::max(d1, d2) <= tolerance) {
      strokes.back().push_back(p3);
      return;
    }
    const Point2 a = 0.5 * (p0 + p1), b = 0.5 * (p1 + p2), c = 0.5 * (p2 + p3);
    const Point2 ab = 0.5 * (a + b), bc = 0.5 * (b + c), m = 0.5 * (ab + bc);
    cubic(p0, a, ab, m, depth + 1);
    cubic(m, bc, c, p3, depth + 1);
  }

  static int move_to(const FT_Vector* to, void* user) {
    auto* f = static_cast<Flattener*>(user);
    f->close_contour();
    f->current = f->point(to);
    f->strokes.push_back({f->current});
    return 0;
  }
  static int line_to(const FT_Vector* to, void* user) {
    auto* f = static_cast<Flattener*>(user);
    f->current = f->point(to);
    f->strokes.back().push_back(f->current);
    return 0;
  }
  static int conic_to(const FT_Vector* control, const FT_Vector* to, void* user) {
    auto* f = static_cast<Flattener*>(user);
    const Point2 end = f->point(to);
    f->quadratic(f->current, f->point(control), end, 0);
    f->current = end;
    return 0;
  }
  static int cubic_to(const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    auto* f = static_cast<Flattener*>(user);
    const Point2 end = f->point(to);
    f->cubic(f->current, f->point(c1), f->point(c2), end, 0);
    f->current = end;
    return 0;
  }
  // Contours are closed: the last point returns to the first.
  void close_contour() {
    if (!strokes.empty() && strokes.back().size() > 1 &&
        (strokes.back().back() - strokes.back().front()).norm() > 0.0) {
      strokes.back().push_back(strokes.back().front());
    }
  }
};

// FreeType's words for the errors a wrong file gives (its own error strings are compiled out
// of Debian's build).
std::string freetype_error(FT_Error e) {
  switch (e) {
    case FT_Err_Unknown_File_Format:
      return "unknown file format";
    case FT_Err_Invalid_File_Format:
      return "broken file";
    case FT_Err_Invalid_Table:
      return "broken table";
    case FT_Err_Invalid_Argument:
      return "invalid data";
    case FT_Err_Invalid_Stream_Operation:
      return "too short or cut";
    default:
      return "error " + std::to_string(e);
  }
}

Result<void> open_font(Library& lib, std::span<const std::byte> data, const std::string& name) {
  if (data.empty()) return fail("font " + name + ": the file is empty");
  if (FT_Init_FreeType(&lib.handle)) return fail("FreeType could not start");
  // FreeType reads the bytes in place for as long as the face lives (the caller keeps them).
  if (const FT_Error e =
          FT_New_Memory_Face(lib.handle, reinterpret_cast<const FT_Byte*>(data.data()),
                             static_cast<FT_Long>(data.size()), 0, &lib.face)) {
    lib.face = nullptr;
    return fail("font " + name + ": not a font FreeType can read (" + freetype_error(e) + ")");
  }
  if (!FT_IS_SCALABLE(lib.face)) return fail("font " + name + ": not an outline font");
  if (lib.face->units_per_EM == 0) return fail("font " + name + ": its em size is 0");
  return {};
}

}  // namespace

std::optional<Error> TextOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance <= 0.0 || tolerance > 0.1) {
    return Error{"text tolerance must be in (0, 0.1] of the em, got " + format_number(tolerance)};
  }
  return std::nullopt;
}

Result<Strokes> text_strokes(std::string_view utf8, const TextOptions& options) {
  // Text problems first: they need no file.
  if (auto error = options.validate()) return fail(error->message);
  if (utf8.empty()) return fail("the text is empty");
  if (!decode_utf8(utf8)) return fail("the text is not valid UTF-8");
  auto bytes = read_file_bytes(options.font, kMaxFontFileBytes);
  if (!bytes) return fail("font " + bytes.error().message);
  return text_strokes_from_font_data(utf8, std::as_bytes(std::span(*bytes)), options.font.string(),
                                     options);
}

Result<Strokes> text_strokes_from_font_data(std::string_view utf8,
                                            std::span<const std::byte> font_data,
                                            std::string_view font_name,
                                            const TextOptions& options) {
  if (auto error = options.validate()) return fail(error->message);
  if (utf8.empty()) return fail("the text is empty");
  const auto text = decode_utf8(utf8);
  if (!text) return fail("the text is not valid UTF-8");
  const std::string font(font_name);
  Library lib;
  if (auto opened = open_font(lib, font_data, font); !opened) return fail(opened.error().message);
  FT_Face face = lib.face;
  const double em = face->units_per_EM;
  // Centre lines come from rendered glyphs: 128 pixels per em is fine enough for a skeleton.
  constexpr int kPixelsPerEm = 128;
  if (options.centerline) FT_Set_Pixel_Sizes(face, 0, kPixelsPerEm);

  Flattener flattener{{}, Point2::Zero(), options.tolerance * em, Point2::Zero()};
  Strokes strokes;
  FT_UInt previous = 0;
  double pen_x = 0.0, pen_y = 0.0;  // font units
  for (char32_t c : *text) {
    if (c == '\n') {
      pen_x = 0.0;
      pen_y -= face->height;
      previous = 0;
      continue;
    }
    const FT_UInt glyph = FT_Get_Char_Index(face, c);
    if (glyph == 0) {
      return fail("font " + font + " has no glyph for " + code_point_name(c));
    }
    if (previous && FT_HAS_KERNING(face)) {
      FT_Vector kerning;
      if (!FT_Get_Kerning(face, previous, glyph, FT_KERNING_UNSCALED, &kerning)) {
        pen_x += static_cast<double>(kerning.x);
      }
    }
    if (options.centerline) {
      // Rendered from the outline (never an embedded bitmap strike) as 8-bit coverage.
      if (FT_Load_Glyph(face, glyph, FT_LOAD_RENDER | FT_LOAD_NO_BITMAP) ||
          face->glyph->bitmap.pixel_mode != FT_PIXEL_MODE_GRAY || face->glyph->bitmap.pitch < 0) {
        return fail("font " + font + ": cannot render " + code_point_name(c));
      }
      const FT_Bitmap& bitmap = face->glyph->bitmap;
      // A broken font can claim a glyph thousands of ems wide: refused before the canvas is
      // allocated. Real glyphs span under two ems; the bound is 4, because thinning a filled
      // 16-em glyph (2048 px square) took longer than the fuzzer's 10 s budget.
      constexpr unsigned kMaxGlyphEms = 4;
      constexpr unsigned kMaxGlyphPixels = kMaxGlyphEms * kPixelsPerEm;
      if (bitmap.rows > kMaxGlyphPixels || bitmap.width > kMaxGlyphPixels) {
        return fail("font " + font + ": " + code_point_name(c) + " is " +
                    std::to_string(bitmap.width) + "x" + std::to_string(bitmap.rows) +
                    " pixels at 128 per em, larger than " + std::to_string(kMaxGlyphEms) + " ems");
      }
      if (bitmap.rows > 0 && bitmap.width > 0) {
        // The glyph on white paper with a margin, then its skeleton as for any image.
        const int margin = 4;
        GrayImage canvas(static_cast<int>(bitmap.width) + 2 * margin,
                         static_cast<int>(bitmap.rows) + 2 * margin);
        for (unsigned y = 0; y < bitmap.rows; ++y) {
          for (unsigned x = 0; x < bitmap.width; ++x) {
            canvas.at(static_cast<int>(x) + margin, static_cast<int>(y) + margin) =
                static_cast<std::uint8_t>(255 -
                                          bitmap.buffer[static_cast<long>(y) * bitmap.pitch + x]);
          }
        }
        ImageStrokeOptions image;
        image.threshold = 127;
        image.polarity = InkPolarity::dark;
        image.speck_fraction = 0.0;
        auto skeleton = image_to_strokes(canvas, image);
        if (!skeleton) {
          return fail("the centre line of " + code_point_name(c) + ": " + skeleton.error().message);
        }
        {
          // Pixels to font units: the canvas's top-left sits at the bitmap's origin.
          const double scale = em / kPixelsPerEm;
          const Point2 origin(pen_x + scale * (face->glyph->bitmap_left - margin),
                              pen_y + scale * (face->glyph->bitmap_top + margin));
          for (Stroke s : skeleton->strokes) {
            for (Point2& p : s) p = origin + scale * p;  // stroke y is already up (negated)
            strokes.push_back(std::move(s));
          }
        }
      }
    } else {
      if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_BITMAP)) {
        return fail("font " + font + ": cannot load " + code_point_name(c));
      }
      FT_Outline_Funcs funcs{};
      funcs.move_to = &Flattener::move_to;
      funcs.line_to = &Flattener::line_to;
      funcs.conic_to = &Flattener::conic_to;
      funcs.cubic_to = &Flattener::cubic_to;
      flattener.offset = Point2(pen_x, pen_y);
      FT_Outline_Decompose(&face->glyph->outline, &funcs, &flattener);
      flattener.close_contour();
    }
    pen_x += static_cast<double>(face->glyph->advance.x) *
             (options.centerline ? em / (64.0 * kPixelsPerEm) : 1.0);
    previous = glyph;
  }
  for (Stroke& s : flattener.strokes) strokes.push_back(std::move(s));
  std::erase_if(strokes, [](const Stroke& s) { return s.size() < 2; });
  if (strokes.empty()) return fail("the text has no visible glyphs");
  for (Stroke& s : strokes) {
    for (Point2& p : s) p /= em;
  }
  return strokes;
}

}  // namespace animkit
