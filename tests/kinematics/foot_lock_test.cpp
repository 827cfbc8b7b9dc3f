// Foot locking (issue 12) on the CMU walk 131_01 and on hand-made trails.
#pragma GCC diagnostic ignored "-Wuninitialized"  // GCC 12 AVX-512 false positive (dense Eigen)
#include "animkit/kinematics/foot_lock.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"

namespace animkit {
namespace {

const std::filesystem::path kWalk = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";
constexpr double kCmuMetresPerUnit = 0.056444;

struct Walk {
  Skeleton skeleton;
  BipedLegs legs;
  SkeletalMotion motion;
};

// The walk in metres, read once for the whole suite; null when the data is absent.
const Walk* walk() {
  static const std::optional<Walk> loaded = []() -> std::optional<Walk> {
    if (!std::filesystem::exists(kWalk)) return std::nullopt;
    auto clip = read_bvh_file(kWalk, {.scale = kCmuMetresPerUnit});
    if (!clip) return std::nullopt;
    auto skeleton = build_skeleton(clip->skeleton);
    if (!skeleton) return std::nullopt;
    auto legs = find_biped_legs(*skeleton);
    if (!legs) return std::nullopt;
    return Walk{*skeleton, *legs, motion_from_bvh(*clip)};
  }();
  return loaded ? &*loaded : nullptr;
}

#define REQUIRE_WALK()                                        \
  const Walk* w = walk();                                     \
  if (w == nullptr) GTEST_SKIP() << kWalk << " is not here"

TEST(FootLockWalk, Diagnostics) {
  REQUIRE_WALK();
  FootLockWorkspace ws;
  SkeletalMotion out;
  const auto r = lock_feet(w->skeleton, w->legs, w->motion, {}, ws, out);
  ASSERT_TRUE(r) << r.error().message;
  const auto& m = r->metrics;
  for (int leg = 0; leg < 2; ++leg) {
    std::printf("leg %d: %d spans:", leg, m.contacts[leg]);
    for (const auto& s : r->contacts[leg].spans) std::printf(" [%d,%d]", s.first, s.last);
    std::printf("\n");
  }
  std::printf("slide before %.3f/%.3f after %.3f/%.3f ik %.3f/%.3f step %.3f %.3f ms %.4f\n",
              m.slide_before_mean_cm, m.slide_before_max_cm, m.slide_after_mean_cm,
              m.slide_after_max_cm, m.ik_error_mean_cm, m.ik_error_max_cm,
              m.max_joint_step_before_cm, m.max_joint_step_after_cm, m.ms_per_frame);
  for (int f = 0; f < w->motion.frame_count(); f += 10) {
    std::printf("%d L %.3f %.3f %.3f R %.3f %.3f %.3f\n", f, r->ankles_before[f * 2].x(),
                r->ankles_before[f * 2].y(), r->ankles_before[f * 2].z(),
                r->ankles_before[f * 2 + 1].x(), r->ankles_before[f * 2 + 1].y(),
                r->ankles_before[f * 2 + 1].z());
  }
}

}  // namespace
}  // namespace animkit
