#pragma once
// Pictures without a window: an offscreen context, the renderer and a multisampled target in
// one object. The CLI uses it for drawing.png, final.png and video frames; tests use it to
// check what a scene looks like.
#include <memory>

#include "animkit/core/image.h"
#include "animkit/render/gl_context.h"
#include "animkit/render/offscreen_target.h"
#include "animkit/render/renderer.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit {

/// Renders DrawLists to Images of a fixed size, with its own offscreen OpenGL context, Renderer
/// and OffscreenTarget (8 samples per pixel, or fewer if the driver offers fewer). Move-only.
class PictureRenderer {
 public:
  /// Makes a renderer for width x height pixel pictures (each side 1..8192). Errors: no OpenGL
  /// context (the message says what was tried), a bad size.
  static Result<PictureRenderer> create(int width, int height);

  /// Takes over the context, renderer and target; `other` is left empty.
  PictureRenderer(PictureRenderer&&) noexcept = default;
  /// Not assignable: the old renderer's OpenGL objects must go while its own context is
  /// current, which a member-wise assignment cannot arrange.
  PictureRenderer& operator=(PictureRenderer&&) = delete;
  /// Makes its context current, so its buffers and shaders are deleted there and not in
  /// whichever context another renderer left current.
  ~PictureRenderer();

  /// Draws `list` seen by `camera` over the background colour and reads the picture back.
  Image render(const DrawList& list, const OrbitCamera& camera,
               Rgba background = palette::background);

  /// Picture width in pixels.
  int width() const { return target_.width(); }
  /// Picture height in pixels.
  int height() const { return target_.height(); }
  /// Width over height, the aspect ratio passed to OrbitCamera::projection().
  double aspect() const { return static_cast<double>(width()) / height(); }
  /// The offscreen context the pictures are drawn in (e.g. for its description()).
  const OffscreenContext& context() const { return context_; }

 private:
  PictureRenderer(OffscreenContext context, Renderer renderer, OffscreenTarget target);
  // Declared in this order so they are destroyed target, renderer, context: GL objects go
  // while their context still exists.
  OffscreenContext context_;
  Renderer renderer_;
  OffscreenTarget target_;
};

}  // namespace animkit
