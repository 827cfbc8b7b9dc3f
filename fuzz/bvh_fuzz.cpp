// Fuzzes the BVH reader and what follows a successful read: the clip is valid, its
// frames pose the skeleton with finite numbers, and it writes and reads back the same.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "animkit/io/bvh.h"
#include "fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using animkit::fuzz::check;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto clip = animkit::read_bvh(text, "fuzz.bvh");
  if (!clip) {
    animkit::fuzz::check_message(clip.error().message, "fuzz.bvh");
    return 0;
  }
  check(!clip->validate(), "a clip read from a file is valid");
  const auto skeleton = animkit::build_skeleton(clip->skeleton);
  check(skeleton.has_value(), "a clip's skeleton builds");
  animkit::SkeletonPose pose = animkit::skeleton_rest_pose(*skeleton);
  for (int f = 0; f < clip->frame_count() && f < 4; ++f) {
    animkit::bvh_frame_to_pose(*clip, f, pose);
    for (const animkit::Quat& q : pose.local_rotations) {
      check(std::abs(q.norm() - 1.0) < 1e-9, "frame rotations are unit quaternions");
    }
  }
  const auto back = animkit::read_bvh(animkit::write_bvh(*clip), "written.bvh");
  check(back.has_value(), "a written clip reads back");
  check(back->skeleton.names == clip->skeleton.names && back->channels == clip->channels &&
            back->end_sites == clip->end_sites && back->motion == clip->motion,
        "a written clip reads back the same");
  return 0;
}
