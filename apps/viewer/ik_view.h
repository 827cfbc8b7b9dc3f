#pragma once
#include <string>
#include <vector>

#include "animkit/scene/ik_scene.h"
#include "scene_view.h"

namespace animkit::viewer {

struct IkViewOptions {
  IkSolverKind solver = IkSolverKind::ccd;
  std::string shape = "star";
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
  IkView(IkScene scene, int shape);
  void follow_cursor(const Cursor& cursor);

  IkScene scene_;
  int shape_ = 0;  // index into all_lab_shapes()
  bool playing_ = true;
  double speed_ = 1.0;    // targets per displayed frame
  double pending_ = 0.0;  // fractional targets carried to the next frame
  bool dragging_ = false;
};

}  // namespace animkit::viewer
