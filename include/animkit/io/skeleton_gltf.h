#pragma once
// A skeleton's motion as glTF 2.0 (.glb): every joint a node, in the skeleton's tree, with its
// rotation (and, where the motion moves it, translation) animated frame by frame, and a simple
// skinned figure (a tapered bone shape from each joint to each child, bound to the joint) so that
// viewers show a body and not only invisible joints. Metres and +Y up, as glTF requires (section
// 3.4, "Coordinate System and Units"): the skeleton's units are converted with the factor given;
// its up axis is taken to be +Y, as in BVH files from motion capture (CMU's among them).
#include <filesystem>
#include <string>

#include "animkit/core/result.h"
#include "animkit/io/bvh.h"
#include "animkit/kinematics/skeletal_motion.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// The .glb bytes of `motion` on `skeleton` (the motion's joint count must be the skeleton's),
/// lengths multiplied by `metres_per_unit` (finite, > 0). Errors: a skeleton that does not
/// validate, a motion of another size or with no frames, a bad factor, past 4 GiB.
Result<std::string> skeleton_glb(const SkeletonDesc& skeleton, const SkeletalMotion& motion,
                                 double metres_per_unit);

/// skeleton_glb of a BVH clip (e.g. metres_per_unit = 0.056444 for a CMU file read at scale 1,
/// 1 for one read at that scale), written to `path` whole or not at all. Errors name the path.
Result<void> write_skeleton_glb_file(const std::filesystem::path& path, const BvhClip& clip,
                                     double metres_per_unit);

}  // namespace animkit
