#pragma once
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "animkit/scene/bvh_scene.h"
#include "scene_view.h"

namespace animkit::viewer {

/// A joint held from the command line: `joint` at its position in the first frame shown plus
/// `offset` (metres).
struct HeldFromStart {
  std::string joint;
  Vec3 offset = Vec3::Zero();
};

struct BvhViewOptions {
  std::string path;         ///< the BVH clip (--bvh); the CMU walk by default
  /// Metres per file unit (--scale); none: told from the legs (bvh_units.h) and printed.
  std::optional<double> scale;
  std::string limits_path;  ///< a joint limits JSON file; empty: human_joint_limits()
  BvhSceneOptions scene;
  int start_frame = 0;
  std::string selected;  ///< the joint whose limit is drawn first (none when empty)
  std::vector<HeldFromStart> held;
  bool close_up = false;  ///< the camera frames the character, not the whole clip's path
};

/// "Motion capture": a BVH clip played and scrubbed, joints dragged as IK targets, foot
/// locking and trails (BvhScene does all of it).
class BvhView final : public SceneView {
 public:
  /// Errors: the file's (read, skeleton, limits), an unknown joint in `selected` or `held`.
  static Result<BvhView> create(const BvhViewOptions& options);

  const char* name() const override { return "Motion capture"; }
  void advance(double seconds) override { scene_.advance(seconds); }
  void toggle_playing() override { scene_.clock().playing = !scene_.clock().playing; }
  void panel() override;
  bool press(const Cursor& cursor) override;
  void drag(const Cursor& cursor) override;
  void release(const Cursor& cursor, bool moved) override;
  void describe(DrawList& out) const override { scene_.describe(out); }
  Eigen::AlignedBox3d focus_bounds() const override;
  double default_yaw() const override { return 0.9; }
  double default_pitch() const override { return 0.3; }

  bool take_new_view() override { return std::exchange(new_view_, false); }

  BvhScene& scene() { return scene_; }

 private:
  BvhView(BvhScene scene, std::string title, bool close_up)
      : scene_(std::move(scene)), title_(std::move(title)), close_up_(close_up) {}

  BvhScene scene_;
  std::string title_;                // the file's name, for the panel
  std::string message_;              // the last refusal (a root cannot be held, ...)
  int dragged_ = -1;                 // the joint under the mouse while a press is held
  Vec3 drag_anchor_ = Vec3::Zero();  // a point of the drag plane (the joint when pressed)
  bool close_up_ = false;            // frame the character, not the clip's whole path
  bool new_view_ = false;            // the framing changed: the camera should follow
};

}  // namespace animkit::viewer
