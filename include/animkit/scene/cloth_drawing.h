#pragma once
// A cloth in a picture: its surface, springs and particles over a floor grid, and where a
// picture of it should look. Shared by ClothScene (the viewer) and the CLI's pictures.
#include <Eigen/Geometry>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/scene/draw_list.h"

namespace animkit {

/// What describe_cloth (and ClothScene::describe) draws. The lab shows the springs; the surface is
/// what users expect.
struct ClothStyle {
  bool surface = true;        ///< lit, two-sided, smooth-shaded triangles
  bool springs = false;       ///< every spring as a line
  bool particles = false;     ///< every particle as a point (pinned ones are always marked)
  double floor_height = 0.0;  ///< y of the ground grid (below where the cloth can hang)
  bool colliders = true;      ///< ClothScene: every collider's surface as it stands
  /// ClothScene: the closest points of every active contact pair (cloth side red, the other
  /// side white, joined by a line).
  bool contacts = false;
};

/// Describes a cloth: ground grid, surface, springs and particles as `style` asks, pinned
/// particles marked. Shared by ClothScene and the CLI's pictures.
void describe_cloth(DrawList& out, const ClothModel& model, const ClothState& state,
                    const ClothStyle& style = {});
/// A box around where a grid cloth is and may swing to: its particles, the flat sheet and the
/// sheet hanging (stretched) down from its pinned edge, so a picture does not jump as it moves.
Eigen::AlignedBox3d cloth_focus_bounds(const GridClothOptions& grid, const ClothState& state);

/// Where a grid cloth's floor goes: below the sheet hanging straight down from its pins,
/// stretched by gravity, so the cloth never passes through the grid.
double cloth_floor_height(const GridClothOptions& grid);

/// The same for any cloth (e.g. cut from a mesh), from its description: the rest shape's box,
/// extended down from its lowest pin (or its lowest point, without pins) by 1.3 times the
/// shape's largest side, so a sheet hanging from its pins stays in the picture. For a grid's
/// description these give the grid overloads' box and floor.
Eigen::AlignedBox3d cloth_focus_bounds(const ClothDesc& desc, const ClothState& state);
/// The floor's height (world y, m) for `desc`: a tenth of the shape's largest side below the
/// lowest point that box reaches.
double cloth_floor_height(const ClothDesc& desc);

/// The direction pictures of the cloth are taken from: facing the hanging sheet's front
/// (orange) side, a little from above.
inline constexpr double kClothPictureYaw = -1.05, kClothPicturePitch = 0.3;  ///< pitch, radians

}  // namespace animkit
