#pragma once
// One scene of the viewer: its side panel, its response to the mouse in the 3D view, what it
// draws. The state and every algorithm live in the library's scene classes; a view only
// connects them to Dear ImGui and the mouse.
#include <Eigen/Geometry>
#include <optional>

#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit::viewer {

/// The cursor in the 3D view: pixel position (y down) and the ray through it.
struct Cursor {
  double x = 0.0, y = 0.0;
  Ray ray;
  const OrbitCamera* camera = nullptr;
  double view_width = 1.0, view_height = 1.0;
};

class SceneView {
 public:
  virtual ~SceneView() = default;
  virtual const char* name() const = 0;
  /// Runs the scene for one displayed frame of `seconds` (when it is playing).
  virtual void advance(double seconds) = 0;
  /// Start / pause (the Space key).
  virtual void toggle_playing() = 0;
  /// Draws the side panel's controls and readouts (inside an open ImGui window).
  virtual void panel() = 0;
  /// A left press in the 3D view: true when the scene takes it (grabs a handle), false to let
  /// the camera orbit instead.
  virtual bool press(const Cursor& cursor) = 0;
  /// The cursor moved while a press the scene took is held.
  virtual void drag(const Cursor& cursor) = 0;
  /// The press ended; `moved` is false for a click.
  virtual void release(const Cursor& cursor, bool moved) = 0;
  virtual void describe(DrawList& out) const = 0;
  /// What the default camera frames.
  virtual Eigen::AlignedBox3d focus_bounds() const = 0;
  virtual double default_yaw() const = 0;
  virtual double default_pitch() const = 0;
  /// True once after the scene changed to one the camera should frame afresh.
  virtual bool take_new_view() { return false; }
};

}  // namespace animkit::viewer
