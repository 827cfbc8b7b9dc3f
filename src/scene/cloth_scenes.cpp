#include "animkit/scene/cloth_scenes.h"

#include <array>
#include <numbers>

#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "animkit/scene/cloth_scene.h"

namespace animkit {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

ColliderDesc sphere(const char* name, double radius, const Vec3& centre, double friction) {
  ColliderDesc c;
  c.name = name;
  c.shape = SphereShape{radius};
  c.motion = ScriptedMotion{.initial = {.position = centre}};
  c.friction = friction;
  return c;
}

ClothWorldDesc lab() {
  return {};
}

// A 1 m sheet falls onto a ball resting on the ground: it wraps the ball, its sides reach the
// ground and its corners fold onto the sheet.
ClothWorldDesc drape_sphere() {
  ClothWorldDesc world = cotton_sheet_world(20, 1.0, 0.6);
  world.colliders.push_back(sphere("ball", 0.25, Vec3(0.0, 0.25, 0.0), 0.3));
  world.ground = GroundDesc{.height = 0.0, .friction = 0.3};
  world.frames = 60;
  return world;
}

// A 1.2 m cloth settles on a 0.8 m square table 0.7 m high: the top holds it by friction,
// the overhang falls and its corners hang in folds.
ClothWorldDesc tablecloth() {
  ClothWorldDesc world = cotton_sheet_world(24, 1.2, 0.75);
  ColliderDesc table;
  table.name = "table";
  table.shape = BoxShape{Vec3(0.4, 0.35, 0.4)};
  table.motion = ScriptedMotion{.initial = {.position = Vec3(0.0, 0.35, 0.0)}};
  table.friction = 0.5;
  world.colliders.push_back(table);
  world.ground = GroundDesc{.height = 0.0, .friction = 0.5};
  world.frames = 60;
  return world;
}

// A 1 m flag on a vertical pole (its edge i = 0 pinned) in a gusting wind along +x; the
// ground far below only turns contact on, so the flag cannot pass through itself.
ClothWorldDesc flag() {
  ClothWorldDesc world = cotton_sheet_world(20, 1.0, 1.6);
  auto& grid = std::get<GridClothOptions>(world.cloth);
  grid.pins = GridPins::edge;
  // Turned upright about the sheet's centre: the pinned edge (along z) becomes vertical.
  grid.rotation = Quat(Eigen::AngleAxisd(90.0 * kDegree, Vec3::UnitX()));
  grid.offset = Vec3::Zero();  // the pole on the y axis
  world.ground = GroundDesc{.height = 0.0, .friction = 0.3};
  AirSettings air;
  air.wind.velocity = Vec3(4.0, 0.0, 0.0);
  air.wind.gust = Vec3(4.0, 0.0, 1.0);
  world.air = air;
  world.frames = 75;
  return world;
}

// A ball turning about the vertical at 2 rad/s under a draped sheet drags it round by friction.
ClothWorldDesc spinning_sphere() {
  ClothWorldDesc world = cotton_sheet_world(20, 1.0, 0.75);
  ColliderDesc ball = sphere("spinning ball", 0.3, Vec3(0.0, 0.4, 0.0), 0.8);
  std::get<ScriptedMotion>(ball.motion).angular_velocity = Vec3(0.0, 2.0, 0.0);
  ball.tessellation = 4;  // facets within 0.2 mm of the true sphere the spin turns
  world.colliders.push_back(ball);
  world.ground = GroundDesc{.height = 0.0, .friction = 0.3};
  world.frames = 75;
  return world;
}

// A sheet dropped edge-first from 0.2 m, nearly upright and a little askew, buckles as it
// lands and piles up on the ground in folds that rest on each other.
ClothWorldDesc fold() {
  ClothWorldDesc world = cotton_sheet_world(20, 0.8, 0.0);
  auto& grid = std::get<GridClothOptions>(world.cloth);
  grid.rotation = Quat(Eigen::AngleAxisd(10.0 * kDegree, Vec3::UnitZ())) *
                  Quat(Eigen::AngleAxisd(75.0 * kDegree, Vec3::UnitX()));
  grid.offset = Vec3(0.0, 0.6, 0.0);
  world.ground = GroundDesc{.height = 0.0, .friction = 0.5};
  world.frames = 75;
  return world;
}

const std::array kScenes{
    ClothSceneEntry{"lab", "the lab's cloth: an 11 x 11 grid hanging from two corners", lab},
    ClothSceneEntry{"drape-sphere",
                    "a cotton sheet falls onto a ball on the ground and folds on itself",
                    drape_sphere},
    ClothSceneEntry{"tablecloth", "a cotton cloth settles over a table, corners hanging",
                    tablecloth},
    ClothSceneEntry{"flag", "a flag pinned on its pole in gusting wind", flag},
    ClothSceneEntry{"spinning-sphere", "a turning ball drags a draped sheet round by friction",
                    spinning_sphere},
    ClothSceneEntry{"fold", "a sheet dropped edge-first piles up on the ground in folds", fold},
};

}  // namespace

ClothWorldDesc cotton_sheet_world(int cells, double size, double height) {
  ClothWorldDesc world;
  GridClothOptions grid;
  grid.cells = cells;
  grid.size = size;
  grid.height = height;
  grid.material = find_material("cotton")->material;
  grid.gravity = 9.81;
  grid.pins = GridPins::none;
  grid.offset = Vec3(-0.5 * size, 0.0, 0.0);  // the grid starts at x = 0: centre it
  world.cloth = grid;
  world.material_name = "cotton";
  use_fast_settings(world);
  world.time_step = 1.0 / 30.0;
  return world;
}

ClothPictureFrame cloth_picture_frame(const ClothWorldDesc& world, const ClothDesc& cloth,
                                      const ClothState& state,
                                      const std::vector<Collider>& colliders) {
  const auto* grid = std::get_if<GridClothOptions>(&world.cloth);
  // The lab's way for a sheet in empty space: room for it to hang from its pins.
  if (!world.has_contact() && grid && grid->pins == GridPins::corners &&
      grid->rotation.coeffs() == Quat::Identity().coeffs())
    return {cloth_focus_bounds(*grid, state), cloth_floor_height(*grid)};
  if (!world.has_contact()) return {cloth_focus_bounds(cloth, state), cloth_floor_height(cloth)};
  // With colliders: the sheet as it starts and every collider, down to the ground.
  Eigen::AlignedBox3d box;
  box.setEmpty();
  for (int i = 0; i < static_cast<int>(state.positions.size() / 3); ++i)
    box.extend(Vec3(state.positions.segment<3>(3 * i)));
  for (const Collider& c : colliders) {
    for (const Vec3& v : c.world_vertices()) box.extend(v);
  }
  double floor = box.min().y();
  if (world.ground) {
    floor = world.ground->height;
    box.extend(Vec3(box.min().x(), floor, box.min().z()));
  }
  return {box, floor};
}

ClothPictureFrame widened_to_hold(ClothPictureFrame frame, const ClothState& state) {
  const double slack = 0.05 * frame.focus.sizes().maxCoeff();
  Eigen::AlignedBox3d inner = frame.focus;
  inner.min().array() -= slack;
  inner.max().array() += slack;
  bool widened = false;
  for (Eigen::Index i = 0; i + 2 < state.positions.size(); i += 3) {
    const Vec3 p = state.positions.segment<3>(i);
    if (!inner.contains(p)) {
      frame.focus.extend(p);
      widened = true;
    }
  }
  if (widened) {
    frame.floor_height = std::min(frame.floor_height, frame.focus.min().y() - slack);
  }
  return frame;
}

std::span<const ClothSceneEntry> cloth_scenes() {
  return kScenes;
}

const ClothSceneEntry* find_cloth_scene(std::string_view name) {
  for (const ClothSceneEntry& entry : kScenes) {
    if (entry.name == name) return &entry;
  }
  return nullptr;
}

std::string cloth_scene_names() {
  std::string names;
  for (const ClothSceneEntry& entry : kScenes)
    names += (names.empty() ? "" : ", ") + std::string(entry.name);
  return names;
}

}  // namespace animkit
