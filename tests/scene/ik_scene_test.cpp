#include "animkit/scene/ik_scene.h"

#include <gtest/gtest.h>

#include <limits>

#include "animkit/trajectory/lab_shapes.h"

namespace animkit {
namespace {

IkScene lab_scene(LabShape shape = LabShape::circle) {
  auto scene = IkScene::create(lab_arm(), Trajectory::all_pen_down(lab_shape_targets(shape)));
  EXPECT_TRUE(scene.has_value()) << scene.error().message;
  return std::move(*scene);
}

TEST(IkScene, AdvanceDrawsThePathOneTargetAtATime) {
  IkScene scene = lab_scene();
  for (int i = 0; i < 10; ++i) {
    const IkSolveReadout& r = scene.advance();
    EXPECT_TRUE(r.result.converged);
    EXPECT_EQ(r.target, scene.targets()[i]);
  }
  ASSERT_EQ(scene.path().size(), 1u);  // one stroke: the pen stays down
  ASSERT_EQ(scene.path().front().size(), 10u);
  EXPECT_EQ(scene.next_target(), 10);
  EXPECT_LE((scene.path().front().back() - scene.targets()[9]).norm(), IkOptions{}.tolerance);
}

TEST(IkScene, ALapEndsFinishedAndTheNextStartsFromRest) {
  IkScene scene = lab_scene(LabShape::square);
  const int n = static_cast<int>(scene.targets().size());
  for (int i = 0; i < n; ++i) scene.advance();
  EXPECT_TRUE(scene.lap_finished());
  EXPECT_EQ(static_cast<int>(scene.path().front().size()), n);
  scene.advance();
  ASSERT_EQ(scene.path().size(), 1u);
  EXPECT_EQ(scene.path().front().size(), 1u);
  EXPECT_EQ(scene.next_target(), 1);
}

TEST(IkScene, FollowingAnUnreachableTargetIsReportedAndDrawn) {
  IkScene scene = lab_scene();
  scene.advance();
  const auto r = scene.follow(Vec3(4.0, 0.0, 0.0));
  ASSERT_TRUE(r.has_value());
  EXPECT_FALSE(r->result.reachable);
  EXPECT_EQ(scene.path().front().size(), 1u);  // dragging does not draw
  DrawList list;
  scene.describe(list);
  bool marked = false;
  for (const PointMarker& p : list.points) {
    marked = marked || ((p.position - Vec3f(4.0f, 0.0f, 0.0f)).norm() < 1e-6f &&
                        p.color.r == palette::unreachable.r && p.color.g == palette::unreachable.g);
  }
  EXPECT_TRUE(marked);
}

TEST(IkScene, DescribesTargetsPathAndArm) {
  IkScene scene = lab_scene(LabShape::star);
  for (int i = 0; i < 50; ++i) scene.advance();
  DrawList list;
  scene.describe(list);
  int targets = 0, path_segments = 0;
  for (const PointMarker& p : list.points) targets += p.color.g == palette::target.g;
  for (const LineSegment& l : list.lines) path_segments += l.color.r == palette::path.r;
  EXPECT_EQ(targets, 400);
  EXPECT_EQ(path_segments, 49);
  EXPECT_FALSE(list.triangles.empty());  // bones and joints
  const Eigen::AlignedBox3d box = scene.focus_bounds();
  EXPECT_TRUE(box.contains(scene.pose().end_effector()));
  EXPECT_TRUE(box.contains(Vec3(0.0, 1.7, 0.0)));  // the root
}

TEST(IkScene, PenUpTravelIsNotDrawn) {
  auto scene =
      IkScene::create(lab_arm(), Trajectory{{Vec3(0.1, 0, 0), Vec3(0.2, 0, 0), Vec3(0.25, 0.05, 0),
                                             Vec3(0.3, 0, 0), Vec3(0.4, 0, 0)},
                                            {1, 1, 0, 1, 1}});
  ASSERT_TRUE(scene.has_value());
  for (int i = 0; i < 5; ++i) scene->advance();
  ASSERT_EQ(scene->path().size(), 2u);
  EXPECT_EQ(scene->path()[0].size(), 2u);
  EXPECT_EQ(scene->path()[1].size(), 2u);
  DrawList list;
  scene->describe(list);
  int grey = 0;
  for (const PointMarker& p : list.points) grey += p.color.r == palette::pen_up.r;
  EXPECT_EQ(grey, 1);
  const auto wrong = IkScene::create(lab_arm(), Trajectory{{Vec3(0.1, 0, 0)}, {1, 0}});
  ASSERT_FALSE(wrong.has_value());
  EXPECT_EQ(wrong.error().message, "the pen list has 2 flags for 1 targets");
}

TEST(IkScene, RejectsBadTargets) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto empty = IkScene::create(lab_arm(), Trajectory{});
  ASSERT_FALSE(empty.has_value());
  EXPECT_EQ(empty.error().message, "the target list is empty");
  IkScene scene = lab_scene();
  const auto bad =
      scene.set_trajectory(Trajectory::all_pen_down({Vec3::Zero(), Vec3(nan, 0.0, 0.0)}));
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().message, "target 1 has a non-finite coordinate (nan, 0, 0)");
  EXPECT_FALSE(scene.follow(Vec3(0.0, nan, 0.0)).has_value());
  EXPECT_EQ(scene.targets().size(), 150u);  // unchanged
}

}  // namespace
}  // namespace animkit
