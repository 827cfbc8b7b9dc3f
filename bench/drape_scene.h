#pragma once
// The drape benchmark's scene, shared by animkit's run and Bullet's: the built-in
// `drape-sphere` (scene/cloth_scenes.h: a flat 1 m cotton sheet 0.6 m up falls onto a 0.25 m
// ball resting on the ground, at dt 1/30 s for 90 frames) with the sheet's resolution chosen
// by the benchmark. Everything else Bullet needs (ball, ground, sheet, material, gravity) is
// read back from that one description, so the two benchmarks cannot drift apart.
#include <stdexcept>
#include <variant>

#include "animkit/cloth/cloth_world.h"
#include "animkit/scene/cloth_scenes.h"

namespace animkit::bench {

/// drape-sphere with `particles` x `particles` particles (>= 2) and at most `frames` frames
/// (the scene's own count when larger).
inline ClothWorldDesc drape_world(int particles, int frames) {
  const ClothSceneEntry* entry = find_cloth_scene("drape-sphere");
  if (entry == nullptr) throw std::logic_error("no built-in scene drape-sphere");
  ClothWorldDesc world = entry->make();
  std::get<GridClothOptions>(world.cloth).cells = particles - 1;
  if (frames < world.frames) world.frames = frames;
  return world;
}

/// The scene's parts in the form another engine takes them.
struct DrapeParts {
  GridClothOptions sheet;  ///< cells, size, height, offset, material, gravity
  double ball_radius = 0.0;
  Vec3 ball_centre = Vec3::Zero();
  double ball_friction = 0.0;
  double ground_height = 0.0;
  double ground_friction = 0.0;
};

inline DrapeParts drape_parts(const ClothWorldDesc& world) {
  DrapeParts parts;
  parts.sheet = std::get<GridClothOptions>(world.cloth);
  const ColliderDesc& ball = world.colliders.at(0);
  parts.ball_radius = std::get<SphereShape>(ball.shape).radius;
  parts.ball_centre = std::get<ScriptedMotion>(ball.motion).initial.position;
  parts.ball_friction = ball.friction;
  parts.ground_height = world.ground.value().height;
  parts.ground_friction = world.ground->friction;
  return parts;
}

}  // namespace animkit::bench
