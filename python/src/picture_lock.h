#pragma once
// What the bindings that render pictures share (bind_pictures.cpp: the cloth's render_png and
// render_image; bind_kin_render.cpp: a drawing run's render_png): the picture sizes the CLI's
// --picture-size takes, and one lock serialising every renderer's life (creation, drawing,
// destruction), which may go through GLFW: GLFW must not be called from two threads at once.
#include <mutex>
#include <optional>
#include <string>

#include "animkit/core/result.h"

namespace animkit::python {

/// The CLI's --picture-size range, pixels per side.
inline constexpr int kMinPictureSide = 16;
inline constexpr int kMaxPictureSide = 8192;

/// The error for a picture size outside the CLI's range, if it is.
inline std::optional<Error> check_picture_size(int width, int height) {
  if (width < kMinPictureSide || width > kMaxPictureSide || height < kMinPictureSide ||
      height > kMaxPictureSide) {
    return Error{"picture size must be between " + std::to_string(kMinPictureSide) + " and " +
                 std::to_string(kMaxPictureSide) + " pixels per side, got " +
                 std::to_string(width) + "x" + std::to_string(height)};
  }
  return std::nullopt;
}

/// Held (with the GIL released) from a PictureRenderer's creation to its destruction: one
/// mutex for the whole module (an inline function's static is one object in every file).
inline std::mutex& picture_renderer_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace animkit::python
