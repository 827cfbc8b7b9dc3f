#pragma once
// Skeletons, limits and seeded random problems shared by the tree IK solver tests, and the
// checks every tree solver must pass (each test file runs them on its own solver).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/io/bvh.h"
#include "animkit/kinematics/tree_ik.h"
#include "limit_samples.h"

namespace animkit::tree_samples {

// A small figure: hips (root), a spine to a chest that is the sub-base of two arms and a head,
// and two legs from the hips; 16 joints, all rest rotations identity.
inline Skeleton figure() {
  SkeletonDesc d;
  const int hips = d.add_joint("hips", -1, Vec3(0, 1, 0));
  const int spine = d.add_joint("spine", hips, Vec3(0, 0.3, 0));
  const int chest = d.add_joint("chest", spine, Vec3(0, 0.3, 0.02));
  d.add_joint("head", chest, Vec3(0, 0.25, 0));
  for (const double side : {1.0, -1.0}) {
    const std::string s = side > 0 ? "l_" : "r_";
    const int shoulder = d.add_joint(s + "shoulder", chest, Vec3(side * 0.2, 0.1, 0));
    const int elbow = d.add_joint(s + "elbow", shoulder, Vec3(side * 0.3, 0, 0));
    d.add_joint(s + "hand", elbow, Vec3(side * 0.25, 0, 0));
    const int hip = d.add_joint(s + "hip", hips, Vec3(side * 0.1, -0.05, 0));
    const int knee = d.add_joint(s + "knee", hip, Vec3(0, -0.45, 0));
    d.add_joint(s + "foot", knee, Vec3(0, -0.4, 0.05));
  }
  return build_skeleton(d).value();
}

// The CMU walk's skeleton in metres, or nothing when the data folder lacks it.
inline std::optional<Skeleton> cmu_skeleton() {
  const std::filesystem::path path = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";
  if (!std::filesystem::exists(path)) return std::nullopt;
  auto clip = read_bvh_file(path, BvhReadOptions{0.056444});
  EXPECT_TRUE(clip) << (clip ? "" : clip.error().message);
  if (!clip) return std::nullopt;
  return build_skeleton(clip->skeleton).value();
}

inline std::vector<int> joints_named(const Skeleton& s, std::initializer_list<const char*> names) {
  std::vector<int> joints;
  for (const char* name : names) {
    joints.push_back(s.find_joint(name));
    EXPECT_GE(joints.back(), 0) << name;
  }
  return joints;
}

// Limits a body might have: knees and elbows hinges (if `hinges`, else balls) about the axis
// perpendicular to their bone and to z, every other non-root joint a ball (swing 1.3 rad,
// twist +-0.7 rad) whose twist axis is its first child's bone, the roots free.
inline std::vector<JointLimit> body_limits(const Skeleton& s, bool hinges = true) {
  std::vector<JointLimit> limits(static_cast<std::size_t>(s.joint_count()), FreeJoint{});
  for (int j = 0; j < s.joint_count(); ++j) {
    if (s.parents()[static_cast<std::size_t>(j)] < 0) continue;
    const std::string& name = s.names()[static_cast<std::size_t>(j)];
    Vec3 bone = Vec3::UnitY();
    if (s.child_count(j) > 0) {
      const Vec3 offset = s.rest_offsets()[static_cast<std::size_t>(
          s.child_list()[static_cast<std::size_t>(s.child_begin()[static_cast<std::size_t>(j)])])];
      if (offset.norm() > 1e-9) bone = offset.normalized();
    }
    auto contains = [&](std::string_view word) {
      std::string lower = name;
      std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
      return lower.find(word) != std::string::npos;
    };
    if (hinges && (contains("knee") || contains("elbow"))) {
      limits[static_cast<std::size_t>(j)] = HingeLimit{
          bone.cross(Vec3::UnitZ()).norm() > 0.5 ? Vec3(bone.cross(Vec3::UnitZ()).normalized())
                                                 : Vec3::UnitX(),
          -2.2, 0.1};
    } else {
      limits[static_cast<std::size_t>(j)] = BallLimit{bone, 1.3, -0.7, 0.7};
    }
  }
  return limits;
}

// The skeleton's rest pose turned by a random rotation inside each joint's limit at every
// joint (angles up to `max_angle` before the limit clamps them), FK run.
inline SkeletonPose random_pose(const Skeleton& s, const std::vector<JointLimit>& limits,
                                std::mt19937_64& rng, double max_angle) {
  SkeletonPose pose = skeleton_rest_pose(s);
  for (int j = 0; j < s.joint_count(); ++j) {
    const auto uj = static_cast<std::size_t>(j);
    Quat turn = limit_samples::about(limit_samples::uniform(rng, 0.0, max_angle),
                                     limit_samples::random_axis(rng));
    if (!limits.empty()) turn = constrain(limits[uj], turn);
    pose.local_rotations[uj] = s.rest_rotations()[uj] * turn;
  }
  skeleton_forward_kinematics(s, pose);
  return pose;
}

// Effectors on `joints` at their positions (and orientations, if asked) in `pose`.
inline std::vector<Effector> effectors_at(const SkeletonPose& pose, const std::vector<int>& joints,
                                          bool with_orientation) {
  std::vector<Effector> effectors;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const auto j = static_cast<std::size_t>(joints[k]);
    Effector e{joints[k], pose.global_positions[j]};
    if (with_orientation) e.orientation = pose.global_rotations[j];
    e.weight = 1.0 + 0.5 * static_cast<double>(k);
    effectors.push_back(e);
  }
  return effectors;
}

inline double max_violation(const Skeleton& s, const std::vector<JointLimit>& limits,
                            const SkeletonPose& pose) {
  double worst = 0.0;
  if (limits.empty()) return worst;
  for (int j = 0; j < s.joint_count(); ++j)
    worst = std::max(worst,
                     violation(limits[static_cast<std::size_t>(j)], relative_to_rest(s, pose, j)));
  return worst;
}

// Bones keep their lengths, roots their positions, and the pose is consistent with FK.
inline void expect_rigid(const Skeleton& s, const SkeletonPose& start, const SkeletonPose& pose) {
  SkeletonPose fk = pose;
  skeleton_forward_kinematics(s, fk);
  for (int j = 0; j < s.joint_count(); ++j) {
    const auto uj = static_cast<std::size_t>(j);
    EXPECT_EQ(pose.local_translations[uj], start.local_translations[uj]) << j;
    EXPECT_LE((fk.global_positions[uj] - pose.global_positions[uj]).norm(), 1e-12) << j;
    const int p = s.parents()[uj];
    if (p < 0) {
      EXPECT_EQ(pose.global_positions[uj], start.global_positions[uj]) << j;
    } else {
      const double length =
          (pose.global_positions[uj] - pose.global_positions[static_cast<std::size_t>(p)]).norm();
      EXPECT_NEAR(length, s.bone_lengths()[uj], 1e-12) << j;
    }
  }
}

inline bool same_bits(const SkeletonPose& a, const SkeletonPose& b) {
  for (std::size_t j = 0; j < a.local_rotations.size(); ++j) {
    if (a.local_rotations[j].coeffs() != b.local_rotations[j].coeffs() ||
        a.global_positions[j] != b.global_positions[j] ||
        a.global_rotations[j].coeffs() != b.global_rotations[j].coeffs())
      return false;
  }
  return true;
}

}  // namespace animkit::tree_samples
