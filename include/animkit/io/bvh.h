#pragma once
// Biovision Hierarchy (BVH) motion files: a skeleton (HIERARCHY) and per-frame channel values
// (MOTION), what motion-capture databases such as CMU's publish and Blender imports and exports.
// Read: any order of the six channels on any joint, End Sites, several roots, '#' comment lines
// (BVH has no comment syntax; some tools write them), any mix of spaces, tabs, CRLF and blank
// lines. Errors are one line: "NAME: line N: what is wrong".
#include <Eigen/Core>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/validation.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// One BVH channel: a translation along, or a rotation about, a parent-frame axis.
enum class BvhChannel : std::uint8_t {
  x_position,
  y_position,
  z_position,
  x_rotation,
  y_rotation,
  z_rotation
};

/// "Xposition", ..., "Zrotation": the channel as a file names it.
std::string_view bvh_channel_name(BvhChannel channel);

/// A motion clip as a BVH file holds it.
struct BvhClip {
  /// The joints in file order (depth first, so parents come first). Offsets in file units
  /// times the read scale. rest_rotations stays empty: BVH rest poses have none.
  SkeletonDesc skeleton;
  /// channels[i]: joint i's channels in file order (at most one of each kind; empty for End
  /// Sites). A joint's local rotation is the product of its rotation channels in this order
  /// (for "Zrotation Xrotation Yrotation": Rz * Rx * Ry); its position channels replace the
  /// matching components of its rest offset (so a root's are its world position).
  std::vector<std::vector<BvhChannel>> channels;
  /// end_sites[i]: joint i is an End Site (a leaf with no channels, no name in the file; named
  /// "<parent>_End" here, plus a number if that is taken). Kept so writing gives them back.
  std::vector<bool> end_sites;
  /// Seconds per frame (> 0); default 1/30 s.
  double frame_time = 1.0 / 30.0;
  /// frames x channel_count(): row f holds frame f's values, columns the joints' channels in
  /// joint order, each joint's in its channels[] order. Rotations in degrees, positions in file
  /// units times the read scale.
  Eigen::MatrixXd motion;

  /// Joints in the skeleton, End Sites included.
  int joint_count() const { return skeleton.joint_count(); }
  /// Frames of motion: the rows of `motion`.
  int frame_count() const { return static_cast<int>(motion.rows()); }
  /// Sum of the joints' channel counts.
  int channel_count() const;
  /// The first problem that keeps this clip from being written (or posed), or nothing: the
  /// skeleton's, sizes that differ, duplicate channels, End Sites with channels or children,
  /// names a file cannot hold (empty, with whitespace, braces or '#'), non-finite values.
  std::optional<Error> validate() const;
};

/// Options of the reader.
struct BvhReadOptions {
  /// Multiplies OFFSETs and position channels (e.g. 0.056444 for CMU's unit to metres).
  /// Finite and > 0; default 1.
  double scale = 1.0;
};

/// Every offset and position value of a clip (file units times the read scale) and every
/// rotation value (degrees) lies in this range: a thousand kilometres in metres or a million
/// in centimetres, and far more turns than any motion, while the skeleton's sums and products
/// stay finite (a Hips Xposition of 1e300 gave infinite joint positions and an "IK error" of
/// inf reported as success).
inline constexpr ParameterRange kBvhValueRange{-1e9, 1e9};

/// Largest BVH file read: hours of dense motion capture, far beyond any clip we animate.
constexpr std::uintmax_t kMaxBvhFileBytes = 512u << 20;

/// The clip in BVH `text`; `name` (the file's) starts every error. Refused, with the line:
/// unexpected or missing keywords and braces, unknown or repeated channels, a CHANNELS count
/// that its list does not match, non-finite or malformed numbers, a frame whose value count
/// differs from the hierarchy's channel count, a "Frames:" count the motion lines contradict,
/// a file that ends early; an empty file; a bad scale.
Result<BvhClip> read_bvh(std::string_view text, std::string_view name,
                         const BvhReadOptions& options = {});

/// read_bvh of the file's bytes; also errors for a missing, unreadable or huge file.
Result<BvhClip> read_bvh_file(const std::filesystem::path& path,
                              const BvhReadOptions& options = {});

/// The clip as BVH text (tabs, "\n" lines), numbers in the shortest form that reads back to
/// the same double. The clip must satisfy validate() (asserted). Joints are written depth
/// first; the motion columns follow that order.
std::string write_bvh(const BvhClip& clip);

/// write_bvh to `path`, whole or not at all (atomic_write.h). validate()'s error names the path.
Result<void> write_bvh_file(const std::filesystem::path& path, const BvhClip& clip);

/// Frame `frame` as local rotations and translations of `pose`, which must have the clip's
/// joint count in all four vectors (globals are left for skeleton_forward_kinematics).
/// Allocates nothing.
void bvh_frame_to_pose(const BvhClip& clip, int frame, SkeletonPose& pose);

/// The inverse: frame `frame`'s values from `pose`. Position channels take the matching
/// components of local_translations; each joint's local rotation is decomposed into Euler
/// angles (degrees) in its channel order (euler_angles.h; gimbal lock gives no NaN). A joint
/// with fewer than 3 rotation channels keeps only the angles about its own axes (exact when
/// the rotation has no component about the missing ones).
void bvh_pose_to_frame(const SkeletonPose& pose, BvhClip& clip, int frame);

}  // namespace animkit
