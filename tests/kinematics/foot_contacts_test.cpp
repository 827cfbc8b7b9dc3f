// Foot locking's settings and contact detection on made-up ankle trails.
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include <gtest/gtest.h>

#include <vector>

#include "animkit/kinematics/foot_lock.h"

namespace animkit {
namespace {

TEST(FootLockSettings, DefaultsAreValidAndErrorsNameTheField) {
  EXPECT_FALSE(FootLockSettings{}.validate());
  FootLockSettings s;
  s.height_threshold = -1;
  EXPECT_EQ(s.validate()->message, "foot lock height threshold must be > 0, got -1");
  s = {};
  s.speed_threshold = 0;
  EXPECT_EQ(s.validate()->message, "foot lock speed threshold must be > 0, got 0");
  s = {};
  s.min_contact_frames = 0;
  EXPECT_EQ(s.validate()->message, "foot lock minimum contact length must be >= 1 frame, got 0");
  s = {};
  s.merge_gap_frames = -2;
  EXPECT_EQ(s.validate()->message, "foot lock gap to merge must be >= 0 frames, got -2");
  s = {};
  s.blend_frames = -1;
  EXPECT_EQ(s.validate()->message, "foot lock blend must be >= 0 frames, got -1");
  s = {};
  s.soft_reach = -0.5;
  EXPECT_EQ(s.validate()->message, "foot lock soft reach must be >= 0 metres, got -0.5");
  s = {};
  s.max_knee_flexion = 4;
  EXPECT_EQ(s.validate()->message,
            "foot lock knee flexion range must satisfy 0 <= min < max <= pi radians, got [0, 4]");
}

TEST(FootLockSettings, KneePoleNamesRoundTrip) {
  for (KneePole p : {KneePole::pelvis_forward, KneePole::original}) {
    EXPECT_EQ(parse_knee_pole(to_string(p)), p);
  }
  EXPECT_FALSE(parse_knee_pole("backward"));
}

TEST(FootContacts, SmoothstepIsFlatAtBothEnds) {
  EXPECT_EQ(smoothstep(-1), 0.0);
  EXPECT_EQ(smoothstep(0), 0.0);
  EXPECT_EQ(smoothstep(0.5), 0.5);
  EXPECT_EQ(smoothstep(1), 1.0);
  EXPECT_EQ(smoothstep(2), 1.0);
  EXPECT_NEAR(smoothstep(1e-4) / 1e-4, 0.0, 1e-3);  // slope ~ 6t near 0
}

// At 10 fps: still on the ground for frames 0..19, a 1 m stride in the air for 20..29, still
// again for 30..49.
std::vector<Vec3> made_up_trail() {
  std::vector<Vec3> trail;
  for (int f = 0; f < 20; ++f) trail.emplace_back(0, 0.1, 0);
  for (int f = 0; f < 10; ++f) trail.emplace_back(0.1 * (f + 1), 0.3, 0);
  for (int f = 0; f < 20; ++f) trail.emplace_back(1.0, 0.1, 0);
  return trail;
}

TEST(FootContacts, FindsLowSlowRunsAndRampsTheWeights) {
  FootLockSettings s;
  s.blend_frames = 3;
  const FootContacts c = detect_foot_contacts(made_up_trail(), 0.1, 0.1, s);
  ASSERT_EQ(c.spans.size(), 2u);
  // Frame 19's central speed is |p20 - p18| / 0.2 s = 1.1 m/s (> 0.35): the first span ends at
  // 18; frame 30's is 1 m/s, so the second starts at 31.
  EXPECT_EQ(c.spans[0].first, 0);
  EXPECT_EQ(c.spans[0].last, 18);
  EXPECT_EQ(c.spans[1].first, 31);
  EXPECT_EQ(c.spans[1].last, 49);
  EXPECT_TRUE(c.spans[0].lock.isApprox(Vec3(0, 0.1, 0)));
  EXPECT_TRUE(c.spans[1].lock.isApprox(Vec3(1, 0.1, 0)));
  EXPECT_EQ(c.weight[18], 1.0);
  EXPECT_EQ(c.weight[19], smoothstep(0.75));
  EXPECT_EQ(c.weight[21], smoothstep(0.25));
  EXPECT_EQ(c.weight[22], 0.0);
  EXPECT_EQ(c.lock[21], c.spans[0].lock);
  EXPECT_EQ(c.lock[28], c.spans[1].lock);
  EXPECT_EQ(c.weight[28], smoothstep(0.25));
  EXPECT_EQ(c.weight[27], 0.0);
  EXPECT_EQ(c.planted[25], 0);
}

TEST(FootContacts, RampsThatMeetMoveTheLockAcrossTheGapWithoutAJump) {
  FootLockSettings s;
  s.blend_frames = 8;  // the 12-frame gap 19..30 is shorter than two ramps
  const FootContacts c = detect_foot_contacts(made_up_trail(), 0.1, 0.1, s);
  ASSERT_EQ(c.spans.size(), 2u);
  double previous_x = 0.0;
  for (int f = 19; f <= 30; ++f) {
    EXPECT_GT(c.weight[f], 0.0) << f;
    EXPECT_GE(c.lock[f].x(), previous_x) << f;  // from the first lock (x 0) to the second (x 1)
    EXPECT_LT(c.lock[f].x() - previous_x, 0.25) << f;
    previous_x = c.lock[f].x();
  }
  EXPECT_EQ(c.lock[31], c.spans[1].lock);
}

TEST(FootContacts, ShortRunsAreDroppedAndShortGapsMerged) {
  std::vector<Vec3> trail(30, Vec3(0, 0.1, 0));
  trail[10].y() = 0.5;  // one frame up: a gap of 3 frames (its neighbours move fast)
  FootLockSettings s;
  EXPECT_EQ(detect_foot_contacts(trail, 0.1, 0.1, s).spans.size(), 1u);
  s.merge_gap_frames = 0;
  const FootContacts split = detect_foot_contacts(trail, 0.1, 0.1, s);
  ASSERT_EQ(split.spans.size(), 2u);
  EXPECT_EQ(split.spans[0].last, 8);
  s.min_contact_frames = 12;  // the first run (9 frames) is too short now
  const FootContacts one = detect_foot_contacts(trail, 0.1, 0.1, s);
  ASSERT_EQ(one.spans.size(), 1u);
  EXPECT_EQ(one.spans[0].first, 12);
  EXPECT_EQ(one.planted[3], 0);
}

}  // namespace
}  // namespace animkit
