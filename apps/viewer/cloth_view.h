#pragma once
#include <string>
#include <utility>
#include <vector>

#include "animkit/scene/cloth_scene.h"
#include "scene_view.h"

namespace animkit::viewer {

/// A scene the menu offers besides the built-in ones (a scene file from the command line).
struct NamedClothWorld {
  std::string name;
  ClothWorldDesc world;
};

/// "Mass-Spring Cloth": any cloth scene of the registry (the lab's by default) or a scene
/// file, with live parameters, mouse dragging and pinning, colliders to grab, contacts shown.
class ClothView final : public SceneView {
 public:
  /// The lab's cloth with `options`.
  static Result<ClothView> create(const ClothSceneOptions& options);
  /// `world` called `name`, which the scene menu also lists when it is not a built-in one.
  static Result<ClothView> create(const ClothWorldDesc& world, const std::string& name);

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
  bool take_new_view() override { return std::exchange(new_view_, false); }

  ClothScene& scene() { return scene_; }
  void set_style(const ClothStyle& style) { style_ = style; }
  void set_playing(bool playing) { playing_ = playing; }

 private:
  explicit ClothView(ClothScene scene);
  void scene_menu();
  void world_controls();
  void readouts();
  void apply(const ClothWorldDesc& world);
  void load(const ClothWorldDesc& world, const std::string& name);
  void step_once();

  ClothScene scene_;
  std::vector<NamedClothWorld> files_;  // scene files the menu lists after the built-in ones
  ClothStyle style_;
  bool playing_ = true;
  bool new_view_ = false;  // a scene was loaded: frame it
  std::string message_;    // the last error (a diverged step, a rejected option)
  std::optional<int> grabbed_;
  bool collider_grabbed_ = false;
  Vec3 grab_plane_point_ = Vec3::Zero();  // the drag moves in the view plane through this
};

}  // namespace animkit::viewer
