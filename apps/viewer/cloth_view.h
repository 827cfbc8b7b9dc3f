#pragma once
#include "animkit/scene/cloth_scene.h"
#include "scene_view.h"

namespace animkit::viewer {

/// "Mass-Spring Cloth": the lab's cloth with live parameters, mouse dragging and pinning.
class ClothView final : public SceneView {
 public:
  static Result<ClothView> create(const ClothSceneOptions& options);

  const char* name() const override { return "Mass-Spring Cloth"; }
  void advance(double seconds) override;
  void toggle_playing() override { playing_ = !playing_; }
  void panel() override;
  bool press(const Cursor& cursor) override;
  void drag(const Cursor& cursor) override;
  void release(const Cursor& cursor, bool moved) override;
  void describe(DrawList& out) const override { scene_.describe(out, style_); }
  Eigen::AlignedBox3d focus_bounds() const override { return scene_.focus_bounds(); }
  double default_yaw() const override { return kClothPictureYaw; }
  double default_pitch() const override { return kClothPicturePitch; }

  ClothScene& scene() { return scene_; }
  void set_style(const ClothStyle& style) { style_ = style; }
  void set_playing(bool playing) { playing_ = playing; }

 private:
  explicit ClothView(ClothScene scene);
  void apply(const ClothSceneOptions& options);
  void step_once();

  ClothScene scene_;
  ClothSceneOptions edited_;  // what the sliders show; applied when it changes
  ClothStyle style_;
  bool playing_ = true;
  std::string message_;  // the last error (a diverged step, a rejected option)
  std::optional<int> grabbed_;
  Vec3 grab_plane_point_ = Vec3::Zero();  // the drag moves in the view plane through this
};

}  // namespace animkit::viewer
