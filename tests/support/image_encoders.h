#pragma once
// Test-side encoders: PNG through libpng and JPEG through libjpeg with every option the
// decoder tests need (bit depths, palettes, interlacing, progressive scans), and BMP and PNM
// built byte by byte, so tests make the files they decode, good and broken.
#include <cstdint>
#include <string>
#include <vector>

namespace animkit::testing_support {

using Bytes = std::vector<std::uint8_t>;

/// A PNG through libpng. `rows` are the raw rows as PNG stores them (samples packed at
/// `bit_depth`, 16-bit samples big-endian), top to bottom.
struct PngSpec {
  int width = 0, height = 0;
  int bit_depth = 8;
  int color_type = 0;  ///< PNG_COLOR_TYPE_*
  std::vector<Bytes> rows;
  std::vector<std::uint8_t> palette;  ///< r, g, b per entry (palette images)
  std::vector<std::uint8_t> alphas;   ///< tRNS: alpha per palette entry
  bool interlaced = false;
};
Bytes png_file(const PngSpec& spec);

/// A PngSpec with its size and format set, rows, palette and tRNS to fill in.
inline PngSpec png_spec(int width, int height, int bit_depth, int color_type) {
  PngSpec spec;
  spec.width = width;
  spec.height = height;
  spec.bit_depth = bit_depth;
  spec.color_type = color_type;
  return spec;
}

/// A JPEG through libjpeg: `samples` are width * height * components (1 gray or 3 RGB).
Bytes jpeg_file(int width, int height, int components, const Bytes& samples, int quality = 100,
                bool progressive = false);

/// A BMP with a 40-byte (or `header_size`) info header. `pixel_rows` are the stored rows,
/// padded to 4 bytes, in file order; `extra` follows the info header (masks, palette as
/// b, g, r, 0). `height` is negative for a top-down file.
Bytes bmp_file(int width, int height, int bpp, const std::vector<Bytes>& pixel_rows,
               const Bytes& extra = {}, std::uint32_t compression = 0,
               std::uint32_t header_size = 40, std::uint32_t colors_used = 0);

/// The bytes of a string literal (PNM headers, bad files).
inline Bytes bytes_of(const std::string& text) {
  return Bytes(text.begin(), text.end());
}

}  // namespace animkit::testing_support
