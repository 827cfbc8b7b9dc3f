#pragma once
// The CMU walk (data/cmu/131_01.bvh) as a skeleton and its motion in metres, for the tests of
// code that takes both.
#include <gtest/gtest.h>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "shared_constants.h"

namespace animkit::testing_support {

inline constexpr double kCmuScale = 0.056444;  // metres per unit of CMU's BVH files

struct CmuWalk {
  Skeleton skeleton;
  SkeletalMotion motion;
};

inline CmuWalk load_cmu_walk() {
  auto clip = read_bvh_file(kWalk, BvhReadOptions{kCmuScale});
  EXPECT_TRUE(clip) << (clip ? "" : clip.error().message);
  // value() throws without the clip, which fails the test (never a read of an empty result).
  return {build_skeleton(clip.value().skeleton).value(), motion_from_bvh(clip.value())};
}

}  // namespace animkit::testing_support
