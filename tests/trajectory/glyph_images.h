#pragma once
// Test images drawn by the tests themselves: thick strokes of ink on white paper, like a
// scanned digit, so skeleton tests need no files.
#include <cmath>

#include "animkit/core/image.h"
#include "animkit/core/types.h"

namespace animkit::testing_support {

/// Paints a disc-brush line of `radius` pixels from a to b (pixel coordinates) in `ink`.
inline void paint_line(GrayImage& im, Eigen::Vector2d a, Eigen::Vector2d b, double radius,
                       std::uint8_t ink = 0) {
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      const Eigen::Vector2d p(x, y), ab = b - a;
      const double t =
          ab.squaredNorm() > 0.0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      if ((a + t * ab - p).norm() <= radius) im.at(x, y) = ink;
    }
  }
}

/// Paints a ring (circle of thickness 2 * radius) centred at c.
inline void paint_ring(GrayImage& im, Eigen::Vector2d c, double r, double radius,
                       std::uint8_t ink = 0) {
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < im.width; ++x) {
      if (std::abs((Eigen::Vector2d(x, y) - c).norm() - r) <= radius) im.at(x, y) = ink;
    }
  }
}

inline GrayImage seven() {
  GrayImage im(64, 64);
  paint_line(im, {14, 12}, {50, 12}, 3.0);
  paint_line(im, {50, 12}, {26, 54}, 3.0);
  return im;
}

inline GrayImage zero() {
  GrayImage im(64, 64);
  paint_ring(im, {32, 32}, 20, 3.0);
  return im;
}

inline GrayImage eight() {
  GrayImage im(64, 80);
  paint_ring(im, {32, 24}, 14, 3.0);
  paint_ring(im, {32, 52}, 14, 3.0);
  return im;
}

inline GrayImage tee() {
  GrayImage im(64, 64);
  paint_line(im, {10, 12}, {54, 12}, 3.0);
  paint_line(im, {32, 12}, {32, 54}, 3.0);
  return im;
}

}  // namespace animkit::testing_support
