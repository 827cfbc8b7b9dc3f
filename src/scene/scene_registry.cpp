#include "animkit/scene/scene_registry.h"

#include <vector>

#include "animkit/scene/cloth_scenes.h"

namespace animkit {

namespace {

std::vector<SceneEntry> make_entries() {
  std::vector<SceneEntry> entries = {
      {"ik", SceneKind::ik, "the lab's arm drawing a shape; drag its tip"},
      {"bvh", SceneKind::bvh,
       "a motion-capture clip (the CMU walk by default): play and scrub, joint limits, drag "
       "joints as effector targets, foot locking and foot trails"},
  };
  for (const ClothSceneEntry& cloth : cloth_scenes()) {
    entries.push_back({cloth.name, SceneKind::cloth, cloth.summary});
  }
  return entries;
}

}  // namespace

std::string_view scene_kind_title(SceneKind kind) {
  switch (kind) {
    case SceneKind::ik:
      return "IK arm";
    case SceneKind::bvh:
      return "Motion capture";
    case SceneKind::cloth:
      return "Cloth";
  }
  return "?";
}

std::span<const SceneEntry> scene_entries() {
  static const std::vector<SceneEntry> entries = make_entries();
  return entries;
}

const SceneEntry* find_scene(std::string_view name) {
  if (name == "cloth") name = cloth_scenes().front().name;
  for (const SceneEntry& entry : scene_entries()) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

std::string scene_names() {
  std::string names;
  for (const SceneEntry& entry : scene_entries()) {
    if (!names.empty()) names += ", ";
    names += entry.name;
  }
  return names;
}

}  // namespace animkit
