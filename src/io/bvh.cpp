// BvhClip's invariants and its frames as poses; the reader and the writer live in
// bvh_reader.cpp and bvh_writer.cpp.
#include "animkit/io/bvh.h"

#include <cassert>
#include <cmath>
#include <numbers>

#include "animkit/kinematics/euler_angles.h"
#include "bvh_text.h"

namespace animkit {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

int axis_of(BvhChannel channel) {
  return static_cast<int>(channel) % 3;
}
bool is_rotation(BvhChannel channel) {
  return static_cast<int>(channel) >= 3;
}

// A joint's rotation order completed to three axes: its rotation channels in file order, then
// the axes it lacks. The angles of missing axes are 0 when composing and dropped when
// decomposing. Returns how many of the three are the joint's own.
int rotation_order(const std::vector<BvhChannel>& channels, EulerOrder& order) {
  int count = 0;
  bool used[3] = {false, false, false};
  for (BvhChannel c : channels) {
    if (is_rotation(c)) {
      order[count++] = axis_of(c);
      used[axis_of(c)] = true;
    }
  }
  int filled = count;
  for (int a = 0; a < 3; ++a) {
    if (!used[a]) order[filled++] = a;
  }
  return count;
}

}  // namespace

std::string_view bvh_channel_name(BvhChannel channel) {
  switch (channel) {
    case BvhChannel::x_position:
      return "Xposition";
    case BvhChannel::y_position:
      return "Yposition";
    case BvhChannel::z_position:
      return "Zposition";
    case BvhChannel::x_rotation:
      return "Xrotation";
    case BvhChannel::y_rotation:
      return "Yrotation";
    case BvhChannel::z_rotation:
      return "Zrotation";
  }
  return "?";
}

int BvhClip::channel_count() const {
  int count = 0;
  for (const auto& list : channels) count += static_cast<int>(list.size());
  return count;
}

std::optional<Error> BvhClip::validate() const {
  if (auto error = skeleton.validate()) return error;
  const std::size_t n = skeleton.names.size();
  if (!skeleton.rest_rotations.empty()) {
    return Error{"a BVH skeleton has no rest rotations, but rest_rotations is not empty"};
  }
  if (channels.size() != n || end_sites.size() != n) {
    return Error{"channels has " + std::to_string(channels.size()) + " and end_sites " +
                 std::to_string(end_sites.size()) + " entries for " + std::to_string(n) +
                 " joints"};
  }
  for (std::size_t i = 0; i < n; ++i) {
    const std::string name = bvh_detail::shown_name(skeleton.names[i]);
    if (skeleton.names[i].find_first_of(bvh_detail::kNotInNames) != std::string::npos) {
      return Error{"joint " + std::to_string(i) + " name '" + name +
                   "' has whitespace, a brace or '#', which a BVH file cannot hold"};
    }
    bool seen[6] = {false, false, false, false, false, false};
    for (BvhChannel c : channels[i]) {
      if (seen[static_cast<int>(c)]) {
        return Error{"joint " + name + " lists " + std::string(bvh_channel_name(c)) + " twice"};
      }
      seen[static_cast<int>(c)] = true;
    }
    if (end_sites[i]) {
      if (!channels[i].empty()) return Error{"End Site " + name + " has channels"};
      if (skeleton.parents[i] < 0) return Error{"End Site " + name + " has no parent"};
    }
    const int p = skeleton.parents[i];
    if (p >= 0 && end_sites[p]) {
      return Error{"joint " + name + " is a child of End Site " +
                   bvh_detail::shown_name(skeleton.names[p])};
    }
  }
  if (motion.cols() != channel_count()) {
    return Error{"motion has " + std::to_string(motion.cols()) + " columns for " +
                 std::to_string(channel_count()) + " channels"};
  }
  if (channel_count() == 0 && frame_count() > 0) {
    return Error{"the clip has frames but no channels (a BVH frame line would be empty)"};
  }
  if (!(std::isfinite(frame_time) && frame_time > 0.0)) {
    return Error{"frame_time must be a finite number of seconds > 0"};
  }
  for (Eigen::Index f = 0; f < motion.rows(); ++f) {
    for (Eigen::Index c = 0; c < motion.cols(); ++c) {
      if (!std::isfinite(motion(f, c))) {
        return Error{"motion value " + std::to_string(c) + " of frame " + std::to_string(f) +
                     " is not finite"};
      }
    }
  }
  return std::nullopt;
}

void bvh_frame_to_pose(const BvhClip& clip, int frame, SkeletonPose& pose) {
  assert(frame >= 0 && frame < clip.frame_count());
  const int n = clip.joint_count();
  assert(static_cast<int>(pose.local_rotations.size()) == n);
  assert(static_cast<int>(pose.local_translations.size()) == n);
  int column = 0;
  for (int j = 0; j < n; ++j) {
    Vec3 translation = clip.skeleton.rest_offsets[j];
    Quat rotation = Quat::Identity();
    // Rotation channels compose left to right in file order: "Z X Y" is Rz * Rx * Ry.
    for (BvhChannel c : clip.channels[j]) {
      const double value = clip.motion(frame, column++);
      if (is_rotation(c)) {
        rotation =
            rotation * Quat(Eigen::AngleAxisd(value * kRadiansPerDegree, Vec3::Unit(axis_of(c))));
      } else {
        translation[axis_of(c)] = value;
      }
    }
    pose.local_rotations[j] = rotation;
    pose.local_translations[j] = translation;
  }
}

void bvh_pose_to_frame(const SkeletonPose& pose, BvhClip& clip, int frame) {
  assert(frame >= 0 && frame < clip.frame_count());
  const int n = clip.joint_count();
  assert(static_cast<int>(pose.local_rotations.size()) == n);
  assert(static_cast<int>(pose.local_translations.size()) == n);
  int column = 0;
  for (int j = 0; j < n; ++j) {
    EulerOrder order{};
    rotation_order(clip.channels[j], order);
    const Vec3 angles = quat_to_euler(order, pose.local_rotations[j]) / kRadiansPerDegree;
    int rotation_index = 0;
    for (BvhChannel c : clip.channels[j]) {
      clip.motion(frame, column++) =
          is_rotation(c) ? angles[rotation_index++] : pose.local_translations[j][axis_of(c)];
    }
  }
}

}  // namespace animkit
