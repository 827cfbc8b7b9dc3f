#include "animkit/scene/bvh_scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/kinematics/human_limits.h"
#include "animkit/scene/skeleton_drawing.h"
#include "cmu_walk.h"

namespace animkit {
namespace {

using testing_support::CmuWalk;
using testing_support::load_cmu_walk;

BvhScene walk_scene(const BvhSceneOptions& options = {}) {
  CmuWalk walk = load_cmu_walk();
  auto scene = BvhScene::create(std::move(walk.skeleton), std::move(walk.motion), {}, options);
  EXPECT_TRUE(scene) << (scene ? "" : scene.error().message);
  return std::move(scene.value());
}

// FK by hand: each joint's world transform composed from the root down, independently of
// skeleton_forward_kinematics.
Vec3 world_position(const Skeleton& s, const SkeletalMotion& m, int frame, int joint) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  std::vector<int> path;
  for (int j = joint; j >= 0; j = s.parents()[j]) path.insert(path.begin(), j);
  for (int j : path) {
    const std::size_t k = static_cast<std::size_t>(frame * m.joint_count + j);
    t = t * Eigen::Translation3d(m.local_translations[k]) * m.local_rotations[k];
  }
  return t.translation();
}

TEST(BvhScene, PlaysTheClipFrameByFrame) {
  BvhScene scene = walk_scene();
  const SkeletalMotion& m = scene.motion();
  scene.advance(10.5 * m.frame_time);
  ASSERT_EQ(scene.clock().frame(), 10);
  const int ankle = scene.skeleton().find_joint("LeftAnkle");
  EXPECT_LE((scene.pose().global_positions[ankle] - world_position(scene.skeleton(), m, 10, ankle))
                .norm(),
            1e-12);
  scene.clock().playing = false;
  scene.advance(1.0);
  EXPECT_EQ(scene.clock().frame(), 10);
  scene.seek(200);
  EXPECT_EQ(scene.clock().frame(), 200);
  EXPECT_LE((scene.pose().global_positions[ankle] - world_position(scene.skeleton(), m, 200, ankle))
                .norm(),
            1e-12);
  EXPECT_FALSE(scene.last_solve());  // nothing held: the clip as captured
}

TEST(BvhScene, ADraggedHandReachesItsTargetWithinLimitsWhileTheFeetStay) {
  for (TreeIkSolverKind solver : {TreeIkSolverKind::dls, TreeIkSolverKind::fabrik}) {
    BvhSceneOptions options;
    options.solver = solver;
    BvhScene scene = walk_scene(options);
    scene.seek(100);
    const Skeleton& s = scene.skeleton();
    const int wrist = s.find_joint("LeftWrist");
    const Vec3 target = scene.clip_pose().global_positions[wrist] + Vec3(0.05, 0.25, 0.15);
    ASSERT_TRUE(scene.hold(wrist, target));
    ASSERT_TRUE(scene.last_solve());
    EXPECT_EQ(scene.last_solve()->effectors, 3);  // the hand and both pinned ankles
    EXPECT_LE((scene.pose().global_positions[wrist] - target).norm(), 2e-3) << to_string(solver);
    for (const char* foot : {"LeftAnkle", "RightAnkle"}) {
      const int j = s.find_joint(foot);
      EXPECT_LE((scene.pose().global_positions[j] - scene.clip_pose().global_positions[j]).norm(),
                2e-3)
          << foot << " " << to_string(solver);
    }
    for (int j = 0; j < s.joint_count(); ++j) {
      EXPECT_LE(violation(scene.limits()[j], relative_to_rest(s, scene.pose(), j)), 1e-9)
          << s.names()[j];
    }
    // The target is held as the clip plays on, and let go the pose is the clip's again.
    scene.seek(110);
    EXPECT_LE((scene.pose().global_positions[wrist] - target).norm(), 2e-3) << to_string(solver);
    scene.let_go(wrist);
    EXPECT_TRUE(scene.held().empty());
    EXPECT_EQ(scene.pose().global_positions[wrist], scene.clip_pose().global_positions[wrist]);
  }
}

TEST(BvhScene, WithoutPinnedFeetOnlyTheHeldJointIsAnEffector) {
  BvhScene scene = walk_scene();
  scene.set_pin_feet(false);
  const int knee = scene.skeleton().find_joint("RightKnee");
  ASSERT_TRUE(scene.hold(knee, scene.clip_pose().global_positions[knee] + Vec3(0, 0.05, 0.1)));
  EXPECT_EQ(scene.last_solve()->effectors, 1);
  // A held ankle replaces its own pin.
  scene.set_pin_feet(true);
  const int ankle = scene.skeleton().find_joint("LeftAnkle");
  ASSERT_TRUE(scene.hold(ankle, scene.clip_pose().global_positions[ankle] + Vec3(0, 0.1, 0)));
  EXPECT_EQ(scene.last_solve()->effectors, 3);  // knee, left ankle held, right ankle pinned
}

TEST(BvhScene, HoldingRefusesRootsBadJointsAndNonFiniteTargets) {
  BvhScene scene = walk_scene();
  auto root = scene.hold(0, Vec3::Zero());
  ASSERT_FALSE(root);
  EXPECT_EQ(root.error().message, "joint Hips is a root: IK turns joints but never moves a root");
  auto out_of_range = scene.hold(99, Vec3::Zero());
  ASSERT_FALSE(out_of_range);
  EXPECT_EQ(out_of_range.error().message, "no joint 99 (the skeleton has 38)");
  auto nan = scene.hold(3, Vec3(0, std::nan(""), 0));
  ASSERT_FALSE(nan);
  EXPECT_EQ(nan.error().message, "the target of LeftKnee (0, nan, 0) is not finite or beyond 1e9");
  auto far = scene.hold(3, Vec3(2e9, 0, 0));  // solve() would refuse it on every frame
  ASSERT_FALSE(far);
  EXPECT_EQ(far.error().message,
            "the target of LeftKnee (2e+09, 0, 0) is not finite or beyond 1e9");
  EXPECT_TRUE(scene.held().empty());
}

TEST(BvhScene, FootLockingSwapsTheClipAndItsTrailsSlideLess) {
  BvhScene scene = walk_scene();
  ASSERT_NE(scene.foot_lock(), nullptr) << scene.foot_lock_problem();
  const int frames = scene.clock().frame_count();
  const FootLockResult& lock = *scene.foot_lock();
  for (int leg = 0; leg < 2; ++leg) {
    const auto before = scene.foot_trail(leg, false), after = scene.foot_trail(leg, true);
    ASSERT_EQ(static_cast<int>(before.size()), frames);
    ASSERT_EQ(static_cast<int>(after.size()), frames);
    // Over each contact the locked trail barely moves; the captured one slides.
    double slide_before = 0.0, slide_after = 0.0;
    for (const FootContactSpan& span : lock.contacts[leg].spans) {
      for (int f = span.first + 1; f <= span.last; ++f) {
        const Vec3 d0 = before[f] - before[f - 1], d1 = after[f] - after[f - 1];
        slide_before += std::hypot(d0.x(), d0.z());
        slide_after += std::hypot(d1.x(), d1.z());
      }
    }
    EXPECT_GT(lock.contacts[leg].spans.size(), 0u);
    EXPECT_LT(slide_after, 0.25 * slide_before) << leg;
  }
  const int ankle = scene.skeleton().find_joint("LeftAnkle");
  const FootContactSpan& span = lock.contacts[0].spans.front();
  const int mid = (span.first + span.last) / 2;
  scene.seek(mid);
  const Vec3 captured = scene.pose().global_positions[ankle];
  ASSERT_TRUE(scene.set_foot_locked(true));
  EXPECT_TRUE(scene.foot_locked());
  EXPECT_EQ(scene.clock().frame(), mid);
  EXPECT_LE((scene.pose().global_positions[ankle] - span.lock).norm(), 0.005);
  EXPECT_EQ(scene.pose().global_positions[ankle], scene.foot_trail(0, true)[mid]);
  EXPECT_NE(scene.pose().global_positions[ankle], captured);
}

TEST(BvhScene, WithoutLegsThereIsNoFootLockAndTheSceneStillPlays) {
  SkeletonDesc d;
  d.add_joint("root", -1, Vec3(0, 1, 0));
  d.add_joint("shoulder", 0, Vec3(0, 0.5, 0));
  d.add_joint("hand", 1, Vec3(0, 0.5, 0));
  Skeleton s = build_skeleton(d).value();
  SkeletalMotion m = make_motion(3, 3, 0.1);
  for (int f = 0; f < 3; ++f) {
    for (int j = 0; j < 3; ++j) m.local_translations[f * 3 + j] = s.rest_offsets()[j];
  }
  auto scene = BvhScene::create(std::move(s), m, {});
  ASSERT_TRUE(scene) << scene.error().message;
  EXPECT_EQ(scene->foot_lock(), nullptr);
  EXPECT_FALSE(scene->foot_lock_problem().empty());
  auto lock = scene->set_foot_locked(true);
  ASSERT_FALSE(lock);
  EXPECT_EQ(lock.error().message, scene->foot_lock_problem());
  EXPECT_TRUE(scene->foot_trail(0, false).empty());
  // The shoulder swings the hand a quarter turn (inside its 120 degree cone).
  ASSERT_TRUE(scene->hold(2, Vec3(0.5, 1.5, 0.0)));
  EXPECT_LE((scene->pose().global_positions[2] - Vec3(0.5, 1.5, 0.0)).norm(), 1e-3);
}

TEST(BvhScene, RefusesAMotionOrLimitsThatDoNotFit) {
  CmuWalk walk = load_cmu_walk();
  SkeletalMotion wrong = make_motion(3, 2, 0.1);
  auto a = BvhScene::create(walk.skeleton, wrong, {});
  ASSERT_FALSE(a);
  EXPECT_EQ(a.error().message, "the motion has 3 joints, the skeleton 38");
  auto b = BvhScene::create(walk.skeleton, walk.motion, std::vector<JointLimit>(2, FreeJoint{}));
  ASSERT_FALSE(b);
  EXPECT_EQ(b.error().message, "got 2 joint limits for 38 joints");
  std::vector<JointLimit> limits(38, FreeJoint{});  // 31 joints and 7 end sites
  limits[3] = HingeLimit{Vec3(2, 0, 0), 0.0, 1.0};
  auto c = BvhScene::create(walk.skeleton, walk.motion, limits);
  ASSERT_FALSE(c);
  EXPECT_EQ(c.error().message.rfind("joint LeftKnee: ", 0), 0u) << c.error().message;
}

TEST(BvhScene, PicksTheJointUnderTheCursor) {
  BvhScene scene = walk_scene();
  scene.seek(50);
  const OrbitCamera camera = OrbitCamera::framing(scene.focus_bounds(), 1.5, 0.5, 0.3);
  const int wrist = scene.skeleton().find_joint("RightWrist");
  const auto pixel = camera.project(scene.pose().global_positions[wrist], 900, 600);
  ASSERT_TRUE(pixel);
  EXPECT_EQ(scene.pick_joint(camera, pixel->x() + 2, pixel->y() - 1, 900, 600, 6.0), wrist);
  EXPECT_EQ(scene.pick_joint(camera, 1.0, 1.0, 900, 600, 6.0), -1);
  // A joint on its parent (LHipJoint sits on the hips) is never picked: the root is.
  const auto hips = camera.project(scene.pose().global_positions[0], 900, 600);
  EXPECT_EQ(scene.pick_joint(camera, hips->x(), hips->y(), 900, 600, 1.0), 0);
}

TEST(BvhScene, ADragMovesTheJointUnderTheCursorInThePlaneFacingTheCamera) {
  BvhScene scene = walk_scene();
  scene.seek(300);
  const OrbitCamera camera = OrbitCamera::framing(scene.focus_bounds(), 1.5, 0.9, 0.3);
  const int elbow = scene.skeleton().find_joint("RightElbow");
  const Vec3 anchor = scene.pose().global_positions[elbow];
  const auto pixel = camera.project(anchor, 900, 600);
  ASSERT_TRUE(pixel);
  // The cursor 15 pixels right and 10 up of where the press began.
  const Ray ray = camera.ray_through_pixel(pixel->x() + 15, pixel->y() - 10, 900, 600);
  ASSERT_TRUE(scene.drag_joint(elbow, ray, camera.eye(), anchor));
  ASSERT_EQ(scene.held().size(), 1u);
  const Vec3 target = scene.held()[0].position;
  EXPECT_NEAR((target - anchor).dot((camera.eye() - anchor).normalized()), 0.0, 1e-9);
  const auto seen = camera.project(target, 900, 600);
  EXPECT_NEAR(seen->x(), pixel->x() + 15, 1e-6);
  EXPECT_NEAR(seen->y(), pixel->y() - 10, 1e-6);
  EXPECT_LE((scene.pose().global_positions[elbow] - target).norm(), 2e-3);
  // A ray pointing away from the plane is refused and the target stays.
  const Ray away{anchor + (camera.eye() - anchor) * 0.5, (camera.eye() - anchor).normalized()};
  EXPECT_FALSE(scene.drag_joint(elbow, away, camera.eye(), anchor));
  EXPECT_EQ(scene.held()[0].position, target);
}

TEST(BvhScene, DescribesTrailsSkeletonTargetsAndTheSelectedLimit) {
  BvhScene scene = walk_scene();
  const int frames = scene.clock().frame_count();
  auto count = [](const DrawList& list, Rgba c) {
    int n = 0;
    for (const LineSegment& l : list.lines) {
      n += l.color.r == c.r && l.color.g == c.g && l.color.b == c.b;
    }
    return n;
  };
  DrawList plain;
  scene.describe(plain);
  EXPECT_EQ(count(plain, kTrailBefore), 2 * (frames - 1));
  EXPECT_EQ(count(plain, kTrailAfter), 2 * (frames - 1));
  EXPECT_EQ(count(plain, kLimitColor), 0);
  const FootLockResult& lock = *scene.foot_lock();
  EXPECT_EQ(plain.points.size(), lock.contacts[0].spans.size() + lock.contacts[1].spans.size());
  EXPECT_FALSE(plain.triangles.empty());  // bones and joints

  const int knee = scene.skeleton().find_joint("LeftKnee");
  scene.select(knee);
  ASSERT_TRUE(std::holds_alternative<HingeLimit>(scene.limits()[knee]));
  ASSERT_TRUE(scene.hold(knee, scene.clip_pose().global_positions[knee] + Vec3(0, 0, 0.1)));
  scene.set_trails(false);
  DrawList selected;
  scene.describe(selected);
  EXPECT_EQ(count(selected, kTrailBefore), 0);
  EXPECT_EQ(count(selected, kLimitColor), 48 + 3);  // the arc, its two ends, the axis
  ASSERT_EQ(selected.points.size(), 1u);  // the held target; no trails, so no contact dots
  EXPECT_LE((selected.points[0].position.cast<double>() - scene.held()[0].position).norm(), 1e-6);
}

}  // namespace
}  // namespace animkit
