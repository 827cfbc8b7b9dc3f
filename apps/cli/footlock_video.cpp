#include "footlock_video.h"

#include <algorithm>
#include <limits>

namespace animkit::cli {

namespace {

constexpr double kYaw = 0.9, kPitch = 0.3;
constexpr Rgba kBefore{0.90f, 0.47f, 0.12f, 1.0f};
constexpr double kBoneThickness = 0.035;  // metres

void describe(const Skeleton& skeleton, const SkeletonPose& before, const SkeletonPose& after,
              const FootLockResult& result, int frame, double floor, DrawList& list) {
  list.clear();
  list.add_ground_grid(floor, 12, 0.5, 0.3);
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const int p = skeleton.parents()[j];
    if (p < 0) continue;
    list.add_line(before.global_positions[p], before.global_positions[j], kBefore, 2.0f);
    if (skeleton.bone_lengths()[j] > 1e-9) {
      list.add_bone_box(after.global_positions[p], after.global_positions[j], kBoneThickness,
                        palette::bone);
    }
  }
  for (const FootContacts& c : result.contacts) {
    if (c.planted[frame]) list.add_point(c.lock[frame], palette::target, 10.0f);
  }
}

}  // namespace

Result<void> render_foot_lock_video(const Skeleton& skeleton, const SkeletalMotion& before,
                                    const SkeletalMotion& after, const FootLockResult& result,
                                    PictureOutput& pictures) {
  if (!pictures.wants_video()) return {};
  SkeletonPose pose_before = skeleton_rest_pose(skeleton), pose_after = pose_before;
  // One camera and one floor for the whole clip, so the video does not jump.
  Eigen::AlignedBox3d bounds;
  double floor = std::numeric_limits<double>::max();
  for (int f = 0; f < before.frame_count(); ++f) {
    before.read_frame(f, pose_before);
    skeleton_forward_kinematics(skeleton, pose_before);
    for (const Vec3& p : pose_before.global_positions) {
      bounds.extend(p);
      floor = std::min(floor, p.y());
    }
  }
  const OrbitCamera camera = OrbitCamera::framing(bounds, pictures.aspect(), kYaw, kPitch);
  DrawList list;
  for (int f = 0; f < before.frame_count(); ++f) {
    if (!pictures.take_video_frame()) continue;
    before.read_frame(f, pose_before);
    skeleton_forward_kinematics(skeleton, pose_before);
    after.read_frame(f, pose_after);
    skeleton_forward_kinematics(skeleton, pose_after);
    describe(skeleton, pose_before, pose_after, result, f, floor, list);
    if (auto ok = pictures.add_video_frame(list, camera); !ok) return ok;
  }
  return pictures.finish_video();
}

}  // namespace animkit::cli
