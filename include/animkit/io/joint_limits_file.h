#pragma once
// Joint limits as a JSON file keyed by joint name. Angles in degrees, axes in the
// joint's rest frame (any non-zero length; normalized on reading):
//
// {
//   "LeftKnee": {"type": "hinge", "axis": [0, 0, 1], "min": 0, "max": 150},
//   "LeftHip":  {"type": "ball", "axis": [0, -1, 0], "swing": 80, "twist": [-30, 30]},
//   "LeftShoulder": {"type": "ball", "axis": [1, 0, 0], "swing": [90, 45],
//                    "swing_axis": [0, 0, 1], "twist": [-60, 60]},
//   "Spine":    {"type": "free"}
// }
//
// hinge: "axis", "min", "max" required, min <= max, both in [-180, 180].
// ball: "axis" (the bone's direction at rest) and "swing" (cone half-angle, [0, 180]) required;
// "twist": [min, max] in [-180, 180], default [-180, 180] (free twist). An elliptical cone:
// "swing": [a, b] with "swing_axis" (perpendicular to "axis"): swings up to a degrees about
// swing_axis and b about axis x swing_axis (BallLimit::swing_angle_2).
// Unknown keys and out-of-range values are errors naming the key ("LeftKnee.max: ...").
#include <filesystem>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/kinematics/joint_limits.h"

namespace animkit {

/// Largest joint limits file read.
constexpr std::uintmax_t kMaxJointLimitsFileBytes = 4u << 20;

/// Limits by joint name (angles converted to radians, axes unit); every entry is valid.
using JointLimitSet = std::map<std::string, JointLimit, std::less<>>;

/// The limits in JSON `text`; `source_name` (the file's) starts every error.
Result<JointLimitSet> read_joint_limits(std::string_view text, std::string_view source_name);

/// read_joint_limits of the file's bytes; also errors for a missing, unreadable or huge file.
Result<JointLimitSet> read_joint_limits_file(const std::filesystem::path& path);

/// One limit per joint of a skeleton, in `joint_names` order: the set's limit for that name, or
/// FreeJoint where the set says nothing. A name in the set that no joint has is an error naming
/// it (a typo must not silently leave a joint free).
Result<std::vector<JointLimit>> bind_joint_limits(const JointLimitSet& limits,
                                                  std::span<const std::string> joint_names);

}  // namespace animkit
