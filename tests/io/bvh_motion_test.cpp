// BVH clips as SkeletalMotion and back, on the CMU walk (skipped without the data).
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include "animkit/io/bvh_motion.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <limits>

#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kWalk;

TEST(BvhMotion, RoundTripKeepsThePosesOfEveryFrame) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " is not here";
  const auto clip = read_bvh_file(kWalk);
  ASSERT_TRUE(clip) << clip.error().message;
  const SkeletalMotion motion = motion_from_bvh(*clip);
  EXPECT_EQ(motion.frame_count(), clip->frame_count());
  EXPECT_EQ(motion.joint_count, clip->joint_count());
  EXPECT_EQ(motion.frame_time, clip->frame_time);
  BvhClip back = *clip;
  back.motion.setZero();
  motion_to_bvh(motion, back);
  // Euler angles may come back as another triple for the same rotation: compare the poses.
  const SkeletalMotion again = motion_from_bvh(back);
  for (std::size_t i = 0; i < motion.local_rotations.size(); ++i) {
    ASSERT_LT(again.local_rotations[i].angularDistance(motion.local_rotations[i]), 1e-9) << i;
    ASSERT_LT((again.local_translations[i] - motion.local_translations[i]).norm(), 1e-9) << i;
  }
}

TEST(BvhMotion, ScalingMultipliesOffsetsAndPositionChannelsOnly) {
  ASSERT_TRUE(std::filesystem::exists(kWalk)) << kWalk << " is not here";
  const auto clip = read_bvh_file(kWalk);
  const auto metres = read_bvh_file(kWalk, {.scale = 0.5});
  ASSERT_TRUE(clip && metres);
  BvhClip scaled = *clip;
  ASSERT_TRUE(scale_bvh_clip(scaled, 0.5));
  EXPECT_EQ(scaled.motion, metres->motion);  // positions halved, rotations (degrees) kept
  for (int j = 0; j < clip->joint_count(); ++j) {
    EXPECT_EQ(scaled.skeleton.rest_offsets[j], metres->skeleton.rest_offsets[j]) << j;
  }
  // A factor that would put a value beyond the clip's range, or is not a number > 0, is
  // refused and changes nothing.
  for (const double factor : {1e308, 0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    BvhClip refused = *clip;
    const auto ok = scale_bvh_clip(refused, factor);
    ASSERT_FALSE(ok) << factor;
    EXPECT_EQ(refused.motion, clip->motion);
    EXPECT_EQ(refused.skeleton.rest_offsets, clip->skeleton.rest_offsets);
  }
  EXPECT_EQ(scale_bvh_clip(scaled, 1e308)
                .error()
                .message.rfind("scaling by 1e+308 puts a value beyond 1e+09 (", 0),
            0u);
  // A tiny factor is fine, and raises no floating-point exception on the way (trapped here).
  BvhClip tiny = *clip;
  EXPECT_TRUE(scale_bvh_clip(tiny, 1e-300));
}

}  // namespace
}  // namespace animkit
