#pragma once
// An 8-bit RGBA picture in memory, rows top to bottom: what the renderer captures, the PNG
// writer saves and tests inspect.
#include <cstdint>
#include <vector>

namespace animkit {

/// One RGBA pixel, 8 bits per channel (0..255); a = 255 is opaque. Zero-initialized: transparent
/// black.
struct Pixel {
  /// Red, 0..255.
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  /// \var g
  /// Green, 0..255.
  /// \var b
  /// Blue, 0..255.
  /// \var a
  /// Alpha, 0 transparent .. 255 opaque.
};

/// An 8-bit RGBA picture, rows top to bottom (see the file overview).
struct Image {
  /// Columns, in pixels; 0 for an empty image.
  int width = 0, height = 0;  ///< rows, in pixels; 0 for an empty image
  std::vector<Pixel> pixels;  ///< width * height, row-major, row 0 at the top

  /// An empty 0 x 0 image.
  Image() = default;
  /// A w x h image with every pixel transparent black (0, 0, 0, 0).
  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h) {}
  /// The pixel in column x (0 = left) of row y (0 = top); not bounds-checked.
  Pixel& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// The pixel in column x (0 = left) of row y (0 = top); not bounds-checked.
  const Pixel& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// True when the image holds no pixels.
  bool empty() const { return pixels.empty(); }
};

/// An 8-bit grayscale picture (0 black .. 255 white), rows top to bottom: what the image and
/// text drawings start from.
struct GrayImage {
  /// Columns, in pixels; 0 for an empty image.
  int width = 0, height = 0;         ///< rows, in pixels; 0 for an empty image
  std::vector<std::uint8_t> pixels;  ///< width * height, row-major, row 0 at the top

  /// An empty 0 x 0 image.
  GrayImage() = default;
  /// A w x h image with every pixel set to `fill` (white by default).
  GrayImage(int w, int h, std::uint8_t fill = 255)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  /// The level (0 black .. 255 white) in column x (0 = left) of row y (0 = top); not
  /// bounds-checked.
  std::uint8_t& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// The level (0 black .. 255 white) in column x (0 = left) of row y (0 = top); not
  /// bounds-checked.
  std::uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  /// True when the image holds no pixels.
  bool empty() const { return pixels.empty(); }
};

}  // namespace animkit
