#pragma once
// Default joint limits for a human skeleton with the CMU motion-capture database's joint names
// (data/cmu/131_01.bvh): what `animkit reach` uses when no --limits file is given. The same
// text is shipped as data/limits/cmu_human.json (a test keeps the two equal), to read, copy and
// edit. Balls for the spine, collars, shoulders and wrists, hinges for the elbows (bending
// forward only, about the upper arm's x axis); the legs and the head are left free.
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/kinematics/joint_limits.h"

namespace animkit {

/// The limits as joint_limits_file.h JSON (degrees, keyed by CMU joint name).
std::string_view cmu_human_limits_json();

/// Those limits for the joints named `joint_names`, FreeJoint for joints they do not name; names
/// the skeleton does not have are skipped (a BVH with other names gets free joints). The count
/// of joints that received a limit goes to `limited` when given.
Result<std::vector<JointLimit>> cmu_human_limits(std::span<const std::string> joint_names,
                                                 int* limited = nullptr);

}  // namespace animkit
