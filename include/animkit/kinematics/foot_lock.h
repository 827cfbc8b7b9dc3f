#pragma once
// Foot locking of a biped's motion clip: find where each foot is planted (low and
// slow), pin its ankle there with two-bone leg IK (knees bending forward, within a flexion
// range), blend smoothly into and out of each contact, and keep the rest of the motion as it
// was. Positions are in metres (scale the clip when reading it), Y is up; sliding and errors
// are reported in centimetres.
#include <array>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "animkit/core/result.h"
#include "animkit/core/types.h"
#include "animkit/kinematics/skeletal_motion.h"
#include "animkit/kinematics/skeleton.h"

namespace animkit {

/// The joints of one leg: hip -> knee -> ankle, each the parent of the next.
struct LegJoints {
  /// Skeleton index of the hip joint (-1 until set).
  int hip = -1, knee = -1, ankle = -1;  ///< skeleton index of the ankle, a child of the knee
  /// \var knee
  /// Skeleton index of the knee joint, a child of the hip.
};

/// legs[0] the left leg, legs[1] the right one (the pelvis' forward axis comes from their hips).
using BipedLegs = std::array<LegJoints, 2>;

/// The legs named "<side>Hip", "<side>Knee", "<side>Ankle" with side "Left" and "Right" (CMU's
/// names), or an error naming the missing joint or the broken parent link.
Result<BipedLegs> find_biped_legs(const Skeleton& skeleton);

/// Where the knee is told to point (the two-bone solver's pole), on the frames it solves.
enum class KneePole : std::uint8_t {
  /// Forward of the pelvis: (left hip - right hip) x up, blended from the knee's own bend
  /// direction by the lock weight so a contact starts without a twist of the leg.
  pelvis_forward,
  /// The knee's own bend direction in the original frame (the leg's twist is kept).
  original,
};

/// "pelvis-forward" / "original", and back (nothing for other text).
std::string_view to_string(KneePole pole);
std::optional<KneePole> parse_knee_pole(std::string_view text);

/// Settings of foot locking (lock_feet(), detect_foot_contacts()): contact detection, blending,
/// and the legs' two-bone IK. Lengths in metres, as the clip's positions.
struct FootLockSettings {
  /// A foot can be planted when its ankle is at most this high above the lowest ankle height of
  /// the clip (either foot). Metres, > 0; default 0.05.
  double height_threshold = 0.05;
  /// ... and its ankle moves at most this fast (central difference). Metres per second, > 0;
  /// default 0.35 (a walk's stance foot barely moves; its swing foot moves several m/s).
  double speed_threshold = 0.35;
  /// Planted runs shorter than this many frames are ignored (noise, not a step). >= 1;
  /// default 6 (50 ms at 120 fps).
  int min_contact_frames = 6;
  /// Planted runs separated by at most this many frames are one contact (a one-frame flicker
  /// over a threshold would otherwise split a step into two locks at different places).
  /// >= 0; default 3.
  int merge_gap_frames = 3;
  /// Frames before and after each contact over which the lock weight rises from 0 to 1 (and
  /// falls back), by smoothstep. >= 0; default 10. 0 snaps the foot (a visible pop).
  int blend_frames = 10;
  /// Knee flexion range (0 = straight, positive = knee forward of the hip-ankle line), radians.
  /// The ankle target's distance from the hip is clamped to what this range allows.
  /// 0 <= min_knee_flexion < max_knee_flexion <= pi; defaults 0 and 150 degrees. A minimum
  /// above 0 bends knees the clip holds straighter than that as soon as a blend starts (a
  /// small pop at the blend's first frame): the clip breaks the limit, the lock enforces it.
  double min_knee_flexion = 0.0;
  double max_knee_flexion = 2.6179938779914944;   ///< see min_knee_flexion; radians (150 deg)
  KneePole knee_pole = KneePole::pelvis_forward;  ///< where solved knees point; see KneePole
  /// Soft reach ("soft IK"): within this distance of the straight leg's reach, the ankle's
  /// distance from the hip approaches the full reach exponentially instead of stopping at it.
  /// Without it a target crossing the reach makes the knee snap (flexion grows like the square
  /// root of the distance missing, a near-infinite knee speed); with it the ankle falls short
  /// by a little near full extension. Metres, >= 0 (0: hard); default 0.01.
  double soft_reach = 0.01;

  /// The first problem ("foot lock height threshold must be > 0, got -1"), or nothing.
  std::optional<Error> validate() const;
};

/// A contact: frames first..last (inclusive) in which one foot is planted.
struct FootContactSpan {
  /// The span's first frame, >= 0.
  int first = 0, last = 0;  ///< the span's last frame (inclusive), >= first
  /// Where the ankle is pinned: its mean position over the span (world, metres).
  Vec3 lock = Vec3::Zero();
};

/// One foot's contacts over a clip.
struct FootContacts {
  std::vector<std::uint8_t> planted;   ///< per frame: 1 inside a span
  std::vector<FootContactSpan> spans;  ///< in frame order, disjoint
  /// Per frame: the lock weight in [0, 1] (1 planted, smoothstep ramps within blend_frames of a
  /// span, 0 elsewhere) and the point it pulls the ankle toward (world, metres; zero where the
  /// weight is 0): the span's lock, or, in a gap where the ramps of two spans meet, a smoothstep
  /// mix of both locks from one to the other, so the target never jumps.
  std::vector<double> weight;
  std::vector<Vec3> lock;  ///< per frame: the point the ankle is pulled toward (see `weight`)
};

/// Contacts of one foot from its ankle's world positions (one per frame, metres): planted where
/// the height above `ground_height` is <= the threshold and the speed <= the threshold, in runs
/// of at least min_contact_frames. Settings must be valid (asserted).
FootContacts detect_foot_contacts(const std::vector<Vec3>& ankle, double frame_time,
                                  double ground_height, const FootLockSettings& settings);

/// Smoothstep 3t^2 - 2t^3 of t clamped to [0, 1]: zero slope at both ends, so a blend starts
/// and ends without a kink in the motion.
double smoothstep(double t);

/// Signed knee flexion of a leg at these positions: the angle between thigh and shin in
/// [0, pi], negative when the knee lies behind the hip-ankle line relative to `forward`.
double knee_flexion(const Vec3& hip, const Vec3& knee, const Vec3& ankle, const Vec3& forward);

/// What lock_feet() measured: the contacts, the planted ankles' sliding before and after the
/// lock, the IK's misses, frame-to-frame steps and the run time.
struct FootLockMetrics {
  std::array<int, 2> contacts = {0, 0};        ///< spans per foot
  std::array<int, 2> planted_frames = {0, 0};  ///< frames inside spans, per foot
  /// Horizontal (XZ) motion of a planted ankle between consecutive frames of one span, cm per
  /// frame, over both feet: before and after locking.
  double slide_before_mean_cm = 0.0, slide_before_max_cm = 0.0;  ///< largest slide before locking
  /// Mean slide of a planted ankle after locking, cm per frame (as slide_before_mean_cm).
  double slide_after_mean_cm = 0.0, slide_after_max_cm = 0.0;  ///< largest slide after locking
  /// |ankle - its target| over frames with a weight > 0, cm (reach or the knee range).
  double ik_error_mean_cm = 0.0, ik_error_max_cm = 0.0;  ///< largest |ankle - its target|, cm
  /// Largest move of any joint between consecutive frames, cm, before locking (and after).
  double max_joint_step_before_cm = 0.0, max_joint_step_after_cm = 0.0;  ///< same, after locking
  /// The same over the joints the lock can move (knees, ankles and below).
  double max_leg_step_before_cm = 0.0, max_leg_step_after_cm = 0.0;  ///< same, after locking
  /// Largest change between consecutive frames of any joint's correction (its position after
  /// minus before), cm: a pop into or out of a contact shows here, a smooth blend keeps it low.
  double max_correction_step_cm = 0.0;
  double ms_per_frame = 0.0;  ///< wall time of the lock (detection, solves, metrics) per frame
};

/// What lock_feet() found: each foot's contacts, the metrics, and the ankles' trails.
struct FootLockResult {
  std::array<FootContacts, 2> contacts;  ///< per leg, in BipedLegs order (0 left, 1 right)
  FootLockMetrics metrics;               ///< measurements of the input and the locked output
  /// ankles_before[f * 2 + leg] and ankles_after: ankle world positions per frame (metres).
  std::vector<Vec3> ankles_before, ankles_after;  ///< after locking, laid out as ankles_before
};

/// Caller-owned scratch of lock_feet: sized on the first call for a skeleton and clip length,
/// reused after, so the per-frame loop allocates nothing.
struct FootLockWorkspace {
  /// The frame being locked (its locals read from the clip, FK run).
  SkeletonPose pose;
  /// Per joint: world position in the previous frame.
  std::vector<Vec3> previous_positions;
  std::vector<std::uint8_t> in_leg;  ///< per joint: 1 for a knee, an ankle or below them
  /// Per joint: world position in this frame before the lock.
  std::vector<Vec3> original_positions, corrections;  ///< per joint: last frame's after - before
};

/// Locks the feet of `input` (a motion of `skeleton`) into `output` (resized to match; frames
/// without a lock weight are copied bit for bit). For each frame with a weight w > 0 on a leg:
/// target = ankle + w (lock - ankle), clamped to the knee's flexion range; the two-bone solver
/// turns hip and knee, and the ankle keeps its world orientation. Errors: invalid settings, a
/// motion that does not fit the skeleton, fewer than 2 frames, a bad frame time.
Result<FootLockResult> lock_feet(const Skeleton& skeleton, const BipedLegs& legs,
                                 const SkeletalMotion& input, const FootLockSettings& settings,
                                 FootLockWorkspace& workspace, SkeletalMotion& output);

}  // namespace animkit
