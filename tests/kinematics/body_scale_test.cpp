// The units of a skeleton told from its legs: the CMU walk in each unit it could have been
// written in is recognised, and a body no unit makes human is refused with its leg length.
#include "animkit/kinematics/body_scale.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "../support/shared_constants.h"
#include "animkit/io/bvh.h"

namespace animkit {
namespace {

using testing_support::kWalk;

// The CMU walk's skeleton with its offsets in file units times `factor`.
Skeleton walk_skeleton(double factor) {
  auto clip = read_bvh_file(kWalk, {.scale = factor});
  EXPECT_TRUE(clip) << clip.error().message;
  return build_skeleton(clip.value().skeleton).value();
}

TEST(BodyScale, TheWalkIsRecognisedInEveryUnit) {
  if (!std::filesystem::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  constexpr double kCmu = 0.056444;  // metres per CMU unit
  for (const LengthUnit& unit : kBvhLengthUnits) {
    // The file's numbers as they would be written in `unit`.
    const Skeleton skeleton = walk_skeleton(kCmu / unit.metres);
    const auto body = detect_body_scale(skeleton, find_biped_legs(skeleton).value());
    ASSERT_TRUE(body) << unit.name << ": " << body.error().message;
    EXPECT_EQ(body->unit.name, unit.name);
    EXPECT_NEAR(body->leg_units * unit.metres, 14.2126 * kCmu, 1e-3) << unit.name;
  }
}

TEST(BodyScale, ABodyNoUnitMakesHumanIsRefused) {
  if (!std::filesystem::exists(kWalk)) GTEST_SKIP() << kWalk << " is not here";
  // Legs of 142 units: 1.42 m in centimetres, 3.6 m in inches, 0.14 m in millimetres.
  const Skeleton giant = walk_skeleton(10.0);
  const auto body = detect_body_scale(giant, find_biped_legs(giant).value());
  ASSERT_FALSE(body);
  EXPECT_EQ(body.error().message,
            "cannot tell the units of the skeleton: its legs are 142 units long, which is no "
            "person's leg in metres, centimetres, millimetres, inches or CMU's unit (nearest: "
            "1.42 m in centimetres; a person's are about 0.8 m)");
}

// A biped whose thighs and shins are `bone` long.
Skeleton legs_of_length(double bone) {
  SkeletonDesc desc;
  desc.add_joint("Hips", -1, Vec3::Zero());
  for (const char* side : {"Left", "Right"}) {
    const int hip = desc.add_joint(std::string(side) + "Hip", 0, Vec3::Zero());
    const int knee = desc.add_joint(std::string(side) + "Knee", hip, Vec3(0, -bone, 0));
    desc.add_joint(std::string(side) + "Ankle", knee, Vec3(0, -bone, 0));
  }
  return build_skeleton(desc).value();
}

TEST(BodyScale, LegsOfNoLengthAreRefused) {
  const Skeleton skeleton = legs_of_length(0.0);
  EXPECT_EQ(detect_body_scale(skeleton, find_biped_legs(skeleton).value()).error().message,
            "cannot tell the units of the skeleton: its legs have no length at rest");
}

TEST(BodyScale, TinyAndHugeLegsAreRefusedWithoutAFloatingPointTrap) {
  // (The tests trap division by zero and overflow: log(1e-300 x 0.001) would divide by zero.)
  for (double bone : {1e-300, 1e8}) {
    const Skeleton skeleton = legs_of_length(bone);
    const auto body = detect_body_scale(skeleton, find_biped_legs(skeleton).value());
    ASSERT_FALSE(body);
    EXPECT_EQ(body.error().message.rfind("cannot tell the units of the skeleton: its legs are ", 0),
              0u)
        << body.error().message;
  }
}

}  // namespace
}  // namespace animkit
