#pragma once
// A multisampled framebuffer to draw into without a window, resolved and read back as an
// Image. Needs a current OpenGL context.
#include <memory>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

class OffscreenTarget {
 public:
  /// A width x height target with up to `samples` samples per pixel (capped at what the driver
  /// offers). Errors: a size outside 1..8192, an incomplete framebuffer.
  static Result<OffscreenTarget> create(int width, int height, int samples = 8);

  OffscreenTarget(OffscreenTarget&&) noexcept;
  OffscreenTarget& operator=(OffscreenTarget&&) noexcept;
  ~OffscreenTarget();

  /// Makes this the framebuffer that drawing goes to.
  void bind() const;
  /// Resolves the samples and reads the picture back (row 0 at the top).
  Image read() const;

  int width() const;
  int height() const;
  int samples() const;

 private:
  struct Impl;
  explicit OffscreenTarget(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
