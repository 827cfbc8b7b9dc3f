#include "animkit/kinematics/human_limits.h"

#include <algorithm>
#include <cassert>
#include <cctype>
#include <string>

namespace animkit {

namespace {

bool name_has(const std::string& name, std::string_view word) {
  std::string lower = name;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return lower.find(word) != std::string::npos;
}

}  // namespace

Vec3 joint_bone_direction(const Skeleton& skeleton, int joint) {
  if (joint < 0 || joint >= skeleton.joint_count()) return Vec3::UnitY();
  for (int k = skeleton.child_begin()[joint]; k < skeleton.child_begin()[joint + 1]; ++k) {
    const Vec3& offset = skeleton.rest_offsets()[skeleton.child_list()[k]];
    if (offset.norm() > 1e-9) return offset.normalized();
  }
  return Vec3::UnitY();
}

std::vector<JointLimit> human_joint_limits(const Skeleton& skeleton) {
  std::vector<JointLimit> limits(skeleton.joint_count(), FreeJoint{});
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    if (skeleton.parents()[j] < 0) continue;
    const std::string& name = skeleton.names()[j];
    const Vec3 bone = joint_bone_direction(skeleton, j);
    const bool knee = name_has(name, "knee"), elbow = name_has(name, "elbow");
    if (knee || elbow) {
      // A small turn by t about a = bone x z moves the bone's end by t (a x bone) = t z (for a
      // bone perpendicular to z): forward. Knees (the shin goes back) flex by negative angles,
      // elbows (the forearm comes forward) by positive ones; a few degrees of overextension
      // keep a captured straight limb inside.
      const Vec3 across = bone.cross(Vec3::UnitZ());
      const Vec3 axis = across.norm() > 0.3 ? Vec3(across.normalized()) : Vec3::UnitX();
      limits[j] = knee ? HingeLimit{axis, -kHumanHingeFlexion, kHumanOverextension}
                       : HingeLimit{axis, -kHumanOverextension, kHumanHingeFlexion};
    } else {
      limits[j] = BallLimit{bone, kHumanBallSwing, -kHumanBallTwist, kHumanBallTwist};
    }
  }
  return limits;
}

std::optional<Error> fit_hinge_axes(const Skeleton& skeleton, const SkeletalMotion& motion,
                                    std::vector<JointLimit>& limits) {
  if (motion.joint_count != skeleton.joint_count() ||
      static_cast<int>(limits.size()) != skeleton.joint_count()) {
    return Error{"fitting hinge axes: a motion of " + std::to_string(motion.joint_count) +
                 " joints and " + std::to_string(limits.size()) + " limits for a skeleton of " +
                 std::to_string(skeleton.joint_count()) + " joints"};
  }
  const int frames = motion.frame_count();
  if (frames == 0) return std::nullopt;
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    auto* hinge = std::get_if<HingeLimit>(&limits[j]);
    if (!hinge) continue;
    Vec3 sum = Vec3::Zero();
    for (int f = 0; f < frames; ++f) {
      const Quat q = skeleton.rest_rotations()[j].conjugate() *
                     motion.local_rotations[static_cast<std::size_t>(f) * motion.joint_count + j];
      const Eigen::AngleAxisd turn(q);
      // A rotation by a about n is one by -a about -n: count it on the hinge axis' side.
      const Vec3 vector = turn.angle() * turn.axis();
      sum += vector.dot(hinge->axis) >= 0.0 ? vector : Vec3(-vector);
    }
    if (sum.norm() / frames < 0.05) continue;
    hinge->axis = sum.normalized();
  }
  return std::nullopt;
}

}  // namespace animkit
