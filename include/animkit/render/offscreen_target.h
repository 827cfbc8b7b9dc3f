#pragma once
// A multisampled framebuffer to draw into without a window, resolved and read back as an
// Image. Needs a current OpenGL context.
#include <memory>

#include "animkit/core/image.h"
#include "animkit/core/result.h"

namespace animkit {

/// An offscreen RGBA8 colour + 24-bit depth framebuffer with multisampling, and a single-sample
/// framebuffer it is resolved into for read(). Owns its OpenGL objects; move-only.
class OffscreenTarget {
 public:
  /// A width x height target with up to `samples` samples per pixel (capped at what the driver
  /// offers). Errors: a size outside 1..8192, an incomplete framebuffer.
  static Result<OffscreenTarget> create(int width, int height, int samples = 8);

  /// Takes over the framebuffers; `other` is left empty.
  OffscreenTarget(OffscreenTarget&&) noexcept;
  /// Deletes this target's framebuffers (if any) and takes over `other`'s.
  OffscreenTarget& operator=(OffscreenTarget&&) noexcept;
  /// Deletes the framebuffers and renderbuffers, in the context current at that moment.
  ~OffscreenTarget();

  /// Makes this the framebuffer that drawing goes to.
  void bind() const;
  /// Resolves the samples and reads the picture back (row 0 at the top).
  Image read() const;

  /// Width in pixels.
  int width() const;
  /// Height in pixels.
  int height() const;
  /// Samples per pixel actually used: the requested count clamped to 1..GL_MAX_SAMPLES.
  int samples() const;

 private:
  struct Impl;
  explicit OffscreenTarget(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
