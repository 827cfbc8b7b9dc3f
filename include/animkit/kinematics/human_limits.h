#pragma once
// Plausible joint limits for a human skeleton whose joints carry the usual names (CMU's BVH:
// LeftKnee, RightElbow, ...), for when no limits file is given: knees and elbows are hinges
// that bend one way, every other joint below the root a ball with a wide cone and a twist
// range. Rough anatomy, not a medical model: enough to show what limits do and to keep a
// dragged limb from bending backwards.
#include <optional>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/kinematics/joint_limits.h"
#include "animkit/kinematics/skeletal_motion.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// The hinge range of knees and elbows, radians: the rest pose (0) to 150 degrees of flexion.
inline constexpr double kHumanHingeFlexion = 2.6179938779914944;
/// How far past straight a knee or elbow may go, radians: 5 degrees.
inline constexpr double kHumanOverextension = 0.087266462599716474;
/// A ball joint's cone half-angle and twist range (+-), radians: 120 and 90 degrees.
inline constexpr double kHumanBallSwing = 2.0943951023931957;
inline constexpr double kHumanBallTwist = 1.5707963267948966;

/// The joint's bone direction in its own frame (unit): toward its first child that is not on
/// top of it, else +y (a leaf, or a joint index out of range). What a ball limit's twist axis
/// follows.
Vec3 joint_bone_direction(const Skeleton& skeleton, int joint);

/// One limit per joint: roots free; a joint whose name contains "knee" (any case) a hinge
/// about a = bone x +z (the body faces +z) flexing the bone backwards (-z: angles in
/// [-kHumanHingeFlexion, kHumanOverextension]), a joint named "elbow" the same hinge flexing
/// forwards ([-kHumanOverextension, kHumanHingeFlexion]); every other joint a ball
/// about its bone (the offset of its first child with a non-zero offset, else +y) with swing
/// kHumanBallSwing and twist +-kHumanBallTwist. Axes in the joint's rest frame.
std::vector<JointLimit> human_joint_limits(const Skeleton& skeleton);

/// Turns each hinge's axis to the axis `motion` actually bends that joint about: the mean of
/// its rotation vectors relative to rest over the clip (each taken on the side of the current
/// axis, so the flexion keeps its sign). A captured elbow does not bend about the axis a
/// skeleton's rest pose suggests (CMU's are 30 degrees off, a carrying angle); a hinge about
/// the wrong axis would refuse most of the clip. Hinges the clip barely bends (a mean turn
/// under 0.05 rad) keep their axis. An error (limits untouched) when `motion` or `limits` does
/// not fit `skeleton`.
[[nodiscard]] std::optional<Error> fit_hinge_axes(const Skeleton& skeleton,
                                                  const SkeletalMotion& motion,
                                                  std::vector<JointLimit>& limits);

}  // namespace animkit
