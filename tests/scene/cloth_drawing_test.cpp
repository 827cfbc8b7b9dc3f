#include "animkit/scene/cloth_drawing.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace animkit {
namespace {

TEST(ClothDrawing, TheSurfaceTwoTrianglesPerCellAndThePinsMarked) {
  const BuiltCloth built = *build_cloth(make_grid_cloth({.cells = 4}));
  const ClothModel& model = built.model;
  const ClothState& state = built.state;
  DrawList list;
  describe_cloth(list, model, state, {.floor_height = -1.0});
  EXPECT_EQ(list.triangles.size(), 3u * 2u * 4u * 4u);
  ASSERT_EQ(list.points.size(), 2u);  // the lab's two pinned corners, nothing else
  for (const PointMarker& p : list.points) EXPECT_EQ(p.color.g, palette::pinned.g);
  for (const LineSegment& line : list.lines) {  // the floor grid and axes
    EXPECT_FLOAT_EQ(std::min(line.a.y(), line.b.y()), -1.0f);
  }
  DrawList springs;
  describe_cloth(springs, model, state, {.surface = false, .springs = true, .particles = true});
  EXPECT_TRUE(springs.triangles.empty());
  EXPECT_EQ(springs.points.size(), 25u);
  EXPECT_GE(springs.lines.size(), static_cast<std::size_t>(model.spring_count()));
}

TEST(ClothDrawing, TheFloorIsBelowTheLabsHangingCloth) {
  const GridClothOptions grid;
  // The lab's cloth (k = 100, m = 1, g = 0.3) hangs 1.16 sides below its pins at most.
  EXPECT_LT(cloth_floor_height(grid), grid.height - 1.16 * grid.size);
  const ClothDesc desc = make_grid_cloth(grid);
  EXPECT_DOUBLE_EQ(cloth_floor_height(desc), cloth_floor_height(grid));
  const Eigen::AlignedBox3d box = cloth_focus_bounds(grid, build_cloth(desc)->state);
  EXPECT_LT(box.min().y(), grid.height - 1.16 * grid.size);
  EXPECT_DOUBLE_EQ(box.max().y(), grid.height);
}

}  // namespace
}  // namespace animkit
