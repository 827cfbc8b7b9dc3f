// Joint limits files: a good file read with degrees turned into radians and axes normalized,
// each kind of mistake one exact error naming the key, and limits bound to a skeleton's joints.
#include "animkit/io/joint_limits_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "../support/temp_files.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kPi;

Result<JointLimitSet> parse_limits(const std::string& text) {
  return read_joint_limits(text, "limits.json");
}

std::string limits_error_of(const std::string& text) {
  const auto limits = parse_limits(text);
  return limits ? std::string("(no error)") : limits.error().message;
}

TEST(JointLimitsFile, ReadsHingeBallAndFreeJointsInRadians) {
  const auto limits = parse_limits(R"({
    "LeftKnee": {"type": "hinge", "axis": [0, 0, 2], "min": 0, "max": 150},
    "LeftHip": {"type": "ball", "axis": [0, -1, 0], "swing": 80, "twist": [-30, 30]},
    "Neck": {"type": "ball", "axis": [0, 1, 0], "swing": 180},
    "Spine": {"type": "free"},
    "LeftShoulder": {"type": "ball", "axis": [1, 0, 0], "swing": [90, 45],
                     "swing_axis": [0, 0, 3], "twist": [-60, 60]}
  })");
  ASSERT_TRUE(limits) << limits.error().message;
  ASSERT_EQ(limits->size(), 5u);
  const auto& shoulder = std::get<BallLimit>(limits->at("LeftShoulder"));
  EXPECT_NEAR(shoulder.swing_angle, kPi / 2.0, 1e-15);
  ASSERT_TRUE(shoulder.swing_angle_2);
  EXPECT_NEAR(*shoulder.swing_angle_2, kPi / 4.0, 1e-15);
  EXPECT_EQ(shoulder.swing_axis, Vec3::UnitZ());
  EXPECT_FALSE(std::get<BallLimit>(limits->at("LeftHip")).swing_angle_2);
  const auto& knee = std::get<HingeLimit>(limits->at("LeftKnee"));
  EXPECT_EQ(knee.axis, Vec3::UnitZ());
  EXPECT_EQ(knee.min_angle, 0.0);
  EXPECT_NEAR(knee.max_angle, 150.0 * kPi / 180.0, 1e-15);
  const auto& hip = std::get<BallLimit>(limits->at("LeftHip"));
  EXPECT_EQ(hip.twist_axis, Vec3(0, -1, 0));
  EXPECT_NEAR(hip.swing_angle, 80.0 * kPi / 180.0, 1e-15);
  EXPECT_NEAR(hip.min_twist, -kPi / 6.0, 1e-15);
  EXPECT_NEAR(hip.max_twist, kPi / 6.0, 1e-15);
  const auto& neck = std::get<BallLimit>(limits->at("Neck"));
  EXPECT_LE(neck.swing_angle, kPi);
  EXPECT_NEAR(neck.swing_angle, kPi, 1e-15);
  EXPECT_GE(neck.min_twist, -kPi);  // twist defaults to free, still within [-pi, pi]
  EXPECT_NEAR(neck.min_twist, -kPi, 1e-15);
  EXPECT_NEAR(neck.max_twist, kPi, 1e-15);
  EXPECT_TRUE(std::holds_alternative<FreeJoint>(limits->at("Spine")));
  EXPECT_TRUE(parse_limits("{}"));
}

TEST(JointLimitsFile, EachMistakeIsNamedByItsKey) {
  const std::pair<const char*, const char*> cases[] = {
      {"[1, 2]", "limits.json: expected an object keyed by joint name {\"LeftKnee\": {...}}"},
      {"{", "limits.json: not valid JSON ("},
      {R"({"Knee": {"type": "hinge", "type": "ball"}})",
       "limits.json: the key 'type' appears twice in one object (which one was meant?)"},
      {R"({"Knee": 3})", "limits.json: Knee: expected an object {...}, got a number"},
      {R"({"Knee": {}})", "limits.json: Knee.type: required: \"hinge\", \"ball\" or \"free\""},
      {R"({"Knee": {"type": "hnge"}})",
       "limits.json: Knee.type: unknown joint type 'hnge' (expected \"hinge\", \"ball\" or "
       "\"free\")"},
      {R"({"Knee": {"type": "hinge", "min": 0, "max": 90}})",
       "limits.json: Knee.axis: required for a hinge joint"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 0], "min": 0, "max": 90}})",
       "limits.json: Knee.axis: must not be zero"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 1], "max": 90}})",
       "limits.json: Knee.min: required for a hinge joint"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 1], "min": 0, "max": 200}})",
       "limits.json: Knee.max: 200 degrees is outside [-180, 180]"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 1], "min": 100, "max": 50}})",
       "limits.json: Knee: min 100 degrees is above max 50 degrees"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 1], "min": 0, "max": "90"}})",
       "limits.json: Knee.max: expected a number, got the string '90'"},
      {R"({"Knee": {"type": "hinge", "axis": [0, 0, 1], "min": 0, "max": 90, "axs": 1}})",
       "limits.json: Knee: unknown key 'axs' (this object takes: axis, max, min, type)"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0]}})",
       "limits.json: Hip.swing: required for a ball joint"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": -5}})",
       "limits.json: Hip.swing: -5 degrees is outside [0, 180]"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": 45, "twist": [10]}})",
       "limits.json: Hip.twist: expected two numbers [min, max] in degrees"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": 45, "twist": 10}})",
       "limits.json: Hip.twist: expected an array [...], got a number"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": 45, "twist": [30, -30]}})",
       "limits.json: Hip.twist: min 30 degrees is above max -30 degrees"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": 45, "twist": [-190, 0]}})",
       "limits.json: Hip.twist: -190 degrees is outside [-180, 180]"},
      {R"({"Hip": {"type": "free", "swing": 45}})",
       "limits.json: Hip: unknown key 'swing' (this object takes: type)"},
      {R"({"Arm": {"type": "ball", "axis": [1, 0, 0], "swing": [90, 45]}})",
       "limits.json: Arm.swing_axis: required with two swing angles"},
      {R"({"Arm": {"type": "ball", "axis": [1, 0, 0], "swing": [90, 45], "swing_axis": [1, 1, 0]}})",
       "limits.json: Arm.swing_axis: must be perpendicular to axis (cosine 0.707107)"},
      {R"({"Arm": {"type": "ball", "axis": [1, 0, 0], "swing": [90, 245], "swing_axis": [0, 1, 0]}})",
       "limits.json: Arm.swing: 245 degrees is outside [0, 180]"},
      {R"({"Arm": {"type": "ball", "axis": [1, 0, 0], "swing": [90]}})",
       "limits.json: Arm.swing: expected a number or two numbers [about swing_axis, about the "
       "third "
       "axis] in degrees"},
      {R"({"Arm": {"type": "ball", "axis": [1, 0, 0], "swing": 90, "swing_axis": [0, 1, 0]}})",
       "limits.json: Arm: unknown key 'swing_axis' (this object takes: axis, swing, twist, type)"},
      {R"({"": {"type": "free"}})", "limits.json: a joint name is empty"},
      {R"({"Hip": {"type": "ball", "axis": [0, 1, 0], "swing": 1e999}})",
       "limits.json: not valid JSON ("},
  };
  for (const auto& [text, expected] : cases) {
    const std::string error = limits_error_of(text);
    if (std::string(expected).ends_with("(")) {
      EXPECT_TRUE(error.starts_with(expected)) << text << "\n" << error;
    } else {
      EXPECT_EQ(error, expected) << text;
    }
  }
}

TEST(JointLimitsFile, ReadsAFileAndNamesAMissingOne) {
  const auto dir = testing_support::fresh_dir("joint_limits_file");
  std::ofstream(dir / "limits.json") << R"({"Elbow": {"type": "hinge", "axis": [1, 0, 0],
                                           "min": -10, "max": 145}})";
  const auto limits = read_joint_limits_file(dir / "limits.json");
  ASSERT_TRUE(limits) << limits.error().message;
  EXPECT_NEAR(std::get<HingeLimit>(limits->at("Elbow")).min_angle, -10.0 * kPi / 180.0, 1e-15);
  const auto missing = read_joint_limits_file(dir / "absent.json");
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("absent.json"), std::string::npos)
      << missing.error().message;
}

TEST(JointLimitsFile, BindsLimitsToJointsByNameAndRefusesUnknownNames) {
  const auto limits = parse_limits(R"({
    "LeftKnee": {"type": "hinge", "axis": [0, 0, 1], "min": 0, "max": 150},
    "LeftHip": {"type": "ball", "axis": [0, -1, 0], "swing": 80}
  })");
  ASSERT_TRUE(limits);
  const std::vector<std::string> skeleton = {"Hips", "LeftHip", "LeftKnee", "LeftAnkle"};
  const auto bound = bind_joint_limits(*limits, skeleton);
  ASSERT_TRUE(bound) << bound.error().message;
  ASSERT_EQ(bound->size(), 4u);
  EXPECT_TRUE(std::holds_alternative<FreeJoint>((*bound)[0]));
  EXPECT_TRUE(std::holds_alternative<BallLimit>((*bound)[1]));
  EXPECT_TRUE(std::holds_alternative<HingeLimit>((*bound)[2]));
  EXPECT_TRUE(std::holds_alternative<FreeJoint>((*bound)[3]));
  const std::vector<std::string> other = {"Hips", "LeftHip", "LeftKne"};
  EXPECT_EQ(bind_joint_limits(*limits, other).error().message,
            "joint limits name the joint 'LeftKnee', which the skeleton does not have");
}

}  // namespace
}  // namespace animkit
