#pragma once
// Colour classes and helpers for tests that look at rendered pictures.
#include <cstdlib>
#include <filesystem>
#include <string>

#include "animkit/core/image.h"
#include "animkit/io/png.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit::testing_support {

inline bool is_green(const Pixel& p) {
  return p.g > p.r + 50 && p.g > p.b + 40;
}
inline bool is_red(const Pixel& p) {
  return p.r > p.g + 70 && p.r > p.b + 70;
}
inline bool is_bone_blue(const Pixel& p) {
  return p.b > p.r + 40 && p.b > p.g + 15;
}
inline bool is_cloth_front(const Pixel& p) {  // orange, lit or in shade
  return p.r > p.b + 60 && p.g < p.r;
}
inline bool is_cloth_back(const Pixel& p) {  // blue
  return p.b > p.r + 40;
}
inline bool is_cloth(const Pixel& p) {
  return is_cloth_front(p) || is_cloth_back(p);
}
inline bool is_dark(const Pixel& p) {  // Dear ImGui's dark panels
  return p.r < 60 && p.g < 60 && p.b < 60;
}
/// Pixels of the class in columns x0 .. width-1.
inline int count_pixels(const Image& image, bool (*test)(const Pixel&), int x0 = 0) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = x0; x < image.width; ++x) n += test(image.at(x, y)) ? 1 : 0;
  }
  return n;
}
inline bool is_background(const Pixel& p, Rgba bg = palette::background) {
  const auto near = [](std::uint8_t v, float f) { return std::abs(v - f * 255.0f) <= 3.0f; };
  return near(p.r, bg.r) && near(p.g, bg.g) && near(p.b, bg.b);
}

/// The pixel under a world point, if it projects inside the picture.
inline const Pixel* pixel_at(const Image& image, const OrbitCamera& camera, const Vec3& world) {
  const auto p = camera.project(world, image.width, image.height);
  if (!p) return nullptr;
  const int x = static_cast<int>(p->x()), y = static_cast<int>(p->y());
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return nullptr;
  return &image.at(x, y);
}

/// With ANIMKIT_TEST_PICTURES=DIR set, saves the picture there for a person to look at.
inline void keep_for_inspection(const Image& image, const std::string& name) {
  if (const char* dir = std::getenv("ANIMKIT_TEST_PICTURES")) {
    std::filesystem::create_directories(dir);
    (void)write_png(std::filesystem::path(dir) / (name + ".png"), image);
  }
}

}  // namespace animkit::testing_support
