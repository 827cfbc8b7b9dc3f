// The audit of a whole world's frame: it must report a cloth through a collider or under the
// ground, and nothing for a sheet that touches neither, or the scenes' test proves nothing.
#include "world_audit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <optional>

#include "animkit/scene/cloth_scenes.h"

namespace animkit::audit {
namespace {

// What the audit says of drape-sphere's world with its flat sheet moved to height `y` (m), or
// left where it starts when `y` is absent; `ball_y` gives the ball's lowest and highest y.
std::string problem_with_sheet_at(std::optional<double> y,
                                  std::array<double, 2>* ball_y = nullptr) {
  const ClothWorldDesc desc = find_cloth_scene("drape-sphere")->make();
  auto world = build_cloth_world(desc);
  EXPECT_TRUE(world) << world.error().message;
  if (ball_y) {
    *ball_y = {1e9, -1e9};
    for (const Vec3& v : world->colliders.front().world_vertices())
      *ball_y = {std::min((*ball_y)[0], v.y()), std::max((*ball_y)[1], v.y())};
  }
  ClothState state = world->simulator.state();
  if (y) {
    for (int i = 1; i < state.positions.size(); i += 3) state.positions[i] = *y;
  }
  EXPECT_TRUE(world->simulator.set_state(state));
  return world_frame_problem(*world, desc, 0);
}

TEST(WorldAudit, ASheetAboveEverythingHasNoProblem) {
  EXPECT_EQ(problem_with_sheet_at(std::nullopt), "");
}

TEST(WorldAudit, ASheetThroughTheBallMeetsIt) {
  std::array<double, 2> ball_y{};
  (void)problem_with_sheet_at(std::nullopt, &ball_y);
  EXPECT_EQ(problem_with_sheet_at(0.5 * (ball_y[0] + ball_y[1])),
            "the cloth meets " + find_cloth_scene("drape-sphere")->make().colliders.front().name);
}

TEST(WorldAudit, ASheetUnderTheGroundIsReported) {
  EXPECT_NE(problem_with_sheet_at(-100.0).find("under the ground"), std::string::npos);
}

}  // namespace
}  // namespace animkit::audit
