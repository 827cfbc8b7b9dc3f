#pragma once
// "WIDTHxHEIGHT" command-line sizes, shared by the CLI and the viewer.
#include <cstdio>
#include <optional>
#include <string>

namespace animkit::apps {

struct PixelSize {
  int width = 0, height = 0;
};

/// "960x720" as a size with both sides in [min_side, 8192]; nothing for anything else.
inline std::optional<PixelSize> parse_pixel_size(const std::string& text, int min_side) {
  PixelSize size;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &size.width, &size.height, &tail) != 2) {
    return std::nullopt;
  }
  const auto ok = [&](int side) { return side >= min_side && side <= 8192; };
  if (!ok(size.width) || !ok(size.height)) return std::nullopt;
  return size;
}

}  // namespace animkit::apps
