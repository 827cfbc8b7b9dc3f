// The viewer's BVH scene solves every displayed frame while a joint is held: once its solver
// workspaces are warm, playing the clip (read the frame, FK, build the effectors, solve)
// allocates nothing, whichever tree solver is chosen.
#include <gtest/gtest.h>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/scene/bvh_scene.h"
#include "counting_malloc.h"

namespace animkit {
namespace {

using testing::AllocationCount;

TEST(BvhSceneAllocation, PlayingWithAHeldHandAllocatesNothingOnceWarm) {
  auto clip = read_bvh_file(ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh", BvhReadOptions{0.056444});
  ASSERT_TRUE(clip) << clip.error().message;
  auto scene = BvhScene::create(build_skeleton(clip->skeleton).value(), motion_from_bvh(*clip), {});
  ASSERT_TRUE(scene) << scene.error().message;
  const int wrist = scene->skeleton().find_joint("LeftWrist");
  scene->seek(100);
  ASSERT_TRUE(scene->hold(wrist, scene->clip_pose().global_positions[wrist] + Vec3(0, 0.2, 0.1)));
  for (const TreeIkSolverKind solver : all_tree_ik_solvers()) {
    scene->set_solver(solver);
    for (int f = 100; f < 110; ++f) scene->seek(f);  // warm: the workspace sizes itself
    AllocationCount count;
    for (int f = 110; f < 140; ++f) {
      scene->advance(scene->clock().frame_time());
      scene->seek(f);
    }
    EXPECT_EQ(count.value(), 0u) << to_string(solver);
    ASSERT_TRUE(scene->last_solve());
  }
}

}  // namespace
}  // namespace animkit
