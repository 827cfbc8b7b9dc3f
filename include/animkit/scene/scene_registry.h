#pragma once
// Every scene the viewer opens, in one list: the lab's IK arm, the motion-capture (BVH) scene
// and each built-in cloth scene (cloth_scenes.h). The viewer's --scene choices and menu, the
// CLI's listing and the tests iterate it, so a new scene is added here once.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace animkit {

/// What kind of scene an entry opens (the viewer has one view per kind).
enum class SceneKind : std::uint8_t {
  ik,     ///< the lab's arm drawing a shape (ik_scene.h)
  bvh,    ///< a motion-capture clip: playback, joint limits, dragged effectors, foot locking
  cloth,  ///< a cloth world (cloth_scene.h); the entry's name is its cloth_scenes() name
};

/// One scene the viewer opens: its name, its kind and a one-line summary.
struct SceneEntry {
  std::string_view name;  ///< what --scene takes, e.g. "ik", "bvh", "drape-sphere"
  /// What kind of scene it is, so which of the viewer's views opens it.
  SceneKind kind;
  std::string_view summary;  ///< one line for --help and menus
};

/// The kind's title in menus: "IK arm", "Motion capture", "Cloth".
std::string_view scene_kind_title(SceneKind kind);

/// Every scene: "ik", "bvh", then the cloth scenes in cloth_scenes() order ("lab" first).
std::span<const SceneEntry> scene_entries();

/// The scene called `name`, or null. "cloth" is also accepted, for the lab's cloth.
const SceneEntry* find_scene(std::string_view name);

/// "ik, bvh, lab, drape-sphere, ...", for messages.
std::string scene_names();

}  // namespace animkit
