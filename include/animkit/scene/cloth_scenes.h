#pragma once
// The built-in cloth scenes: one list the CLI (`animkit cloth --scene NAME`), the viewer's
// scene menu, the tests (every frame of every scene audited for intersections) and the
// benchmarks iterate. Each is a ClothWorldDesc (cloth/cloth_world.h), the same data a JSON
// scene file holds.
#include <span>
#include <string>
#include <string_view>

#include "animkit/cloth/cloth_world.h"

namespace animkit {

/// One built-in cloth scene: its name, a one-line summary and the function that makes its world.
struct ClothSceneEntry {
  std::string_view name;     ///< what --scene and the menu take, e.g. "drape-sphere"
  std::string_view summary;  ///< one line for --help and menus
  ClothWorldDesc (*make)();  ///< the scene, with its own frame count and time step
};

/// Every built-in scene, the lab's hanging cloth (the default) first.
std::span<const ClothSceneEntry> cloth_scenes();

/// The scene called `name`, or null.
const ClothSceneEntry* find_cloth_scene(std::string_view name);

/// "lab, drape-sphere, ...", for messages.
std::string cloth_scene_names();

/// Where pictures of a world look: a box around the cloth as it starts and the colliders, and
/// the floor drawn under it (the ground, or below where the sheet can hang).
struct ClothPictureFrame {
  /// The box a picture frames, world space, m.
  Eigen::AlignedBox3d focus;
  /// Height (world y, m) of the floor grid drawn under the cloth.
  double floor_height = 0.0;
};
/// The frame of `world`, whose sheet `cloth` starts in `state` among `colliders` (as built).
ClothPictureFrame cloth_picture_frame(const ClothWorldDesc& world, const ClothDesc& cloth,
                                      const ClothState& state,
                                      const std::vector<Collider>& colliders);

/// The same frame widened to also hold `state`'s particles where they left it (by more than
/// 5% of its largest side), with the floor drawn below them: a picture of a run's end keeps a
/// sheet that stretched or slid away whole (the lab's parameters on a fine grid hang twice as
/// long as their start frame expects).
ClothPictureFrame widened_to_hold(ClothPictureFrame frame, const ClothState& state);

/// The square cotton sheet of `cells` cells per side and `size` m that the contact scenes
/// use: flat at height y, centred on the y axis, free (no pins), gravity 9.81, at dt 1/30 s,
/// solved with use_fast_settings().
ClothWorldDesc cotton_sheet_world(int cells, double size, double height);

}  // namespace animkit
