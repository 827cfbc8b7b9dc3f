#pragma once
// Draws a DrawList with OpenGL 3.3 core: lit two-sided triangles, screen-space-wide lines and
// round point markers. Needs a current context (OffscreenContext or a window's); it draws into
// whatever framebuffer is bound. Each draw sets the state it needs (viewport, depth test,
// blending, program, vertex array) and leaves depth testing on and blending off; callers that
// draw more (Dear ImGui) set their own state.
#include <Eigen/Core>
#include <memory>

#include "animkit/core/result.h"
#include "animkit/scene/draw_list.h"

namespace animkit {

/// The rectangle of the framebuffer to draw into, in pixels from its bottom-left corner (as
/// OpenGL counts them).
struct Viewport {
  /// Width of the rectangle in pixels.
  int width = 0, height = 0;  ///< Height of the rectangle in pixels.
  /// Left edge of the rectangle, in pixels from the framebuffer's left edge.
  int x = 0, y = 0;  ///< Bottom edge of the rectangle, in pixels from the framebuffer's bottom.
};

/// Draws DrawLists with OpenGL 3.3 core into the bound framebuffer. Owns its shader programs,
/// vertex arrays and buffers, which belong to the context current at create(). Move-only.
class Renderer {
 public:
  /// Compiles the shaders and makes the buffers. Errors: a shader that does not compile or
  /// link (with the driver's log), no current context.
  static Result<Renderer> create();

  /// Takes over the programs and buffers; `other` is left empty.
  Renderer(Renderer&&) noexcept;
  /// Deletes this renderer's OpenGL objects (if any) and takes over `other`'s.
  Renderer& operator=(Renderer&&) noexcept;
  /// Deletes the programs and buffers; the context they were made in must be current.
  ~Renderer();

  /// Clears the viewport's rectangle of the bound framebuffer to `background` (colour, depth).
  void clear(const Viewport& viewport, Rgba background) const;
  /// Draws `list`: triangles, then points, then lines (a drawn path covers the targets under
  /// it, as in the lab). Markers are pulled slightly towards the eye, so they stay visible on
  /// the surfaces they lie on. `view` and `projection` as OrbitCamera gives them.
  void draw(const DrawList& list, const Eigen::Matrix4d& view, const Eigen::Matrix4d& projection,
            const Viewport& viewport);

 private:
  struct Impl;
  explicit Renderer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace animkit
