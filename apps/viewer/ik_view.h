#pragma once
#include <string>
#include <vector>

#include "animkit/io/drawing_source.h"
#include "animkit/scene/ik_scene.h"
#include "scene_view.h"

namespace animkit::viewer {

struct IkViewOptions {
  IkSolverKind solver = IkSolverKind::ccd;
  DrawingSource source;  ///< what is drawn first; a custom one joins the shape list
  DrawingLayout layout;
};

/// "Inverse Kinematics": the lab's arm drawing a shape, plus a target to drag.
class IkView final : public SceneView {
 public:
  static Result<IkView> create(const IkViewOptions& options);

  const char* name() const override { return "Inverse Kinematics"; }
  void advance(double seconds) override;
  void toggle_playing() override { playing_ = !playing_; }
  void panel() override;
  bool press(const Cursor& cursor) override;
  void drag(const Cursor& cursor) override;
  void release(const Cursor& cursor, bool moved) override;
  void describe(DrawList& out) const override;
  Eigen::AlignedBox3d focus_bounds() const override { return scene_.focus_bounds(); }
  double default_yaw() const override { return kIkPictureYaw; }
  double default_pitch() const override { return kIkPicturePitch; }

  IkScene& scene() { return scene_; }
  void set_playing(bool playing) { playing_ = playing; }

 private:
  struct Entry {
    std::string name;
    DrawingSource source;
  };
  IkView(IkScene scene, std::vector<Entry> entries, int selected, DrawingLayout layout,
         PreparedDrawing drawing);
  void follow_cursor(const Cursor& cursor);
  // Prepares entry `index` with the current layout and hands it to the scene.
  void select(int index);
  void drawing_panel();

  IkScene scene_;
  std::vector<Entry> entries_;  // the built-in shapes, then custom drawings
  int selected_ = 0;
  DrawingLayout layout_;
  PreparedDrawing drawing_;  // what the scene is drawing, with its spacing numbers
  std::string message_;      // the last error (a font without a glyph, ...)
  char text_[128] = "QD";
  bool playing_ = true;
  double speed_ = 1.0;    // targets per displayed frame
  double pending_ = 0.0;  // fractional targets carried to the next frame
  bool dragging_ = false;
};

}  // namespace animkit::viewer
