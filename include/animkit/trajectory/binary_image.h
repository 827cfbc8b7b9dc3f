#pragma once
// Black-and-white images for skeletons: Otsu's threshold, connected components, speck removal
// and thinning to a one-pixel skeleton (Zhang & Suen 1984; Guo & Hall 1989).
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "animkit/core/image.h"

namespace animkit {

/// A binary image: 1 = ink (foreground), 0 = paper. Pixels outside read as 0.
struct BinaryImage {
  /// Columns, >= 0.
  int width = 0, height = 0;         ///< rows, >= 0
  std::vector<std::uint8_t> pixels;  ///< width * height, row-major, row 0 at the top

  BinaryImage() = default;
  /// A w x h image (w, h >= 0) of paper only.
  BinaryImage(int w, int h) : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, 0) {}
  /// Whether (x, y), column x and row y counted from the top, is a pixel of the image.
  bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
  /// The pixel at column x, row y; 0 (paper) outside the image.
  std::uint8_t get(int x, int y) const {
    return inside(x, y) ? pixels[static_cast<std::size_t>(y) * width + x] : 0;
  }
  /// Sets the pixel at column x, row y to v (0 or 1); (x, y) must be inside() (not checked).
  void set(int x, int y, std::uint8_t v) { pixels[static_cast<std::size_t>(y) * width + x] = v; }
  /// Number of ink pixels (value 1).
  int count() const;
};

/// Otsu's threshold (Otsu 1979): the gray level t maximizing the between-class variance of
/// the classes <= t and > t. Nothing when the image has a single gray level.
std::optional<int> otsu_threshold(const GrayImage& image);

enum class InkPolarity {
  automatic,  ///< the class most of the border has is paper (ties, all-border images: dark ink)
  dark,       ///< pixels <= threshold are ink (pen on paper)
  light,      ///< pixels > threshold are ink (MNIST: white digit on black)
};

/// Ink where the polarity says, relative to `threshold`.
BinaryImage binarize(const GrayImage& image, int threshold, InkPolarity polarity);

/// 8-connected components; returns the component label of every pixel (-1 for paper) and
/// the size of each component.
struct Components {
  std::vector<int> label;  ///< per pixel, as BinaryImage::pixels: its component, -1 for paper
  std::vector<int> sizes;  ///< pixels in each component, indexed by label
};
Components connected_components(const BinaryImage& image);

/// Removes 8-connected components smaller than `min_pixels`; returns how many it removed.
int remove_specks(BinaryImage& image, int min_pixels);

enum class ThinningMethod { zhang_suen, guo_hall };
std::string_view to_string(ThinningMethod method);
std::optional<ThinningMethod> parse_thinning(std::string_view name);

/// Thins the ink to a skeleton one pixel wide that keeps the shape's 8-connectivity (holes
/// stay holes, pieces stay pieces). Zhang-Suen has Lu & Wang's correction for diagonal lines.
/// A 2x2 block of ink is left only where removing any of its pixels would cut the skeleton
/// (at some crossings).
void thin(BinaryImage& image, ThinningMethod method);

}  // namespace animkit
