#pragma once
// An 8-bit RGBA picture in memory, rows top to bottom: what the renderer captures, the PNG
// writer saves and tests inspect.
#include <cstdint>
#include <vector>

namespace animkit {

struct Pixel {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
};

struct Image {
  int width = 0, height = 0;
  std::vector<Pixel> pixels;  ///< width * height, row-major, row 0 at the top

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h) {}
  Pixel& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  const Pixel& at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  bool empty() const { return pixels.empty(); }
};

/// An 8-bit grayscale picture (0 black .. 255 white), rows top to bottom: what the image and
/// text drawings start from.
struct GrayImage {
  int width = 0, height = 0;
  std::vector<std::uint8_t> pixels;  ///< width * height, row-major, row 0 at the top

  GrayImage() = default;
  GrayImage(int w, int h, std::uint8_t fill = 255)
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}
  std::uint8_t& at(int x, int y) { return pixels[static_cast<std::size_t>(y) * width + x]; }
  std::uint8_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
  bool empty() const { return pixels.empty(); }
};

}  // namespace animkit
