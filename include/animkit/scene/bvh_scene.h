#pragma once
// The interactive motion-capture scene: a skeleton clip played, paused and
// scrubbed; any joint dragged to a target and held there by a tree IK solver while the rest
// of the body follows the clip (feet optionally pinned where the clip puts them); the clip
// swapped for its foot-locked version, computed once; and the ankles' trails before and
// after locking. The viewer shows this class; it holds the state and every algorithm.
#include <array>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "animkit/kinematics/foot_lock.h"
#include "animkit/kinematics/tree_ik.h"
#include "animkit/kinematics/tree_ik_solver.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"
#include "animkit/scene/playback_clock.h"

namespace animkit {

/// How a BvhScene solves, makes its foot-locked clip and what it draws.
struct BvhSceneOptions {
  /// CCD by default: on a captured body reaching with a hand it turns the arm and leaves the
  /// spine nearly as captured, where DLS bends every spine joint (its least-norm step favours
  /// joints far from the hand) and FABRIK twists the lower back and chest against each other
  /// (docs/skeletons.md has the measured angles).
  TreeIkSolverKind solver = TreeIkSolverKind::ccd;
  FootLockSettings foot_lock;  ///< how the foot-locked clip is made (metres, Y up)
  bool foot_locked = false;    ///< start on the foot-locked clip (when it can be made)
  /// While targets are held, ankles without a target of their own stay where the clip (the
  /// one shown) puts them: extra effectors, so a dragged hand does not lift a foot.
  bool pin_feet = true;
  bool trails = true;  ///< draw both ankles' trails over the whole clip, before and after
};

/// A joint held at a world position (scene units) by IK.
struct HeldTarget {
  /// Index of the held joint in the skeleton; never a root.
  int joint = -1;
  /// Where IK holds it, world space.
  Vec3 position = Vec3::Zero();
};

/// What the last solve did (for the viewer's readouts).
struct BvhSolveReadout {
  /// What the tree IK solver reported: iterations, error, convergence, reachability.
  TreeIkResult result;
  int effectors = 0;  ///< held targets plus pinned feet
  /// Wall-clock time of the solve, microseconds.
  double solve_time_us = 0.0;
};

/// Colours of the foot trails: the clip as captured (drawn wide, under the other), and after
/// foot locking (narrow, dark, with a dot where each contact pins the ankle). Where locking
/// changed nothing the orange shows as a border of the dark line.
inline constexpr Rgba kTrailBefore{1.00f, 0.50f, 0.05f, 1.0f};
/// The foot-locked clip's trail and its contact dots (see above).
inline constexpr Rgba kTrailAfter{0.08f, 0.12f, 0.40f, 1.0f};

/// The interactive motion-capture scene (see the top of this header): a clip on a
/// PlaybackClock, joints held by tree IK, the foot-locked clip and the ankles' trails. Made by
/// create(); move-only.
class BvhScene {
 public:
  /// `motion` a clip of `skeleton` in metres, Y up; `limits` one per joint (an empty vector:
  /// human_joint_limits() with the hinges' axes fitted to the clip, fit_hinge_axes()). When the
  /// skeleton has CMU-named legs and the clip at least two frames, the foot-locked clip is made
  /// here once; otherwise the scene works without it (foot_lock_problem() says why). Errors: a
  /// motion that does not fit the skeleton or has no frame, a bad frame time, limits of the wrong
  /// count or invalid (naming the joint).
  static Result<BvhScene> create(Skeleton skeleton, SkeletalMotion motion,
                                 std::vector<JointLimit> limits,
                                 const BvhSceneOptions& options = {});
  /// Takes over another scene; the moved-from one may only be destroyed or assigned to.
  BvhScene(BvhScene&&) noexcept;
  /// Replaces this scene with another; the moved-from one may only be destroyed or assigned to.
  BvhScene& operator=(BvhScene&&) noexcept;
  ~BvhScene();

  /// Moves the clock on (when playing) and poses the frame it shows.
  void advance(double seconds);
  /// Shows frame `frame` (clamped) and poses it.
  void seek(int frame);
  /// The clock, to play, pause or change speed; move it with advance() and seek(), which also
  /// pose the frame.
  PlaybackClock& clock() { return clock_; }
  /// The clock: the frame shown, the time and the clip's duration.
  const PlaybackClock& clock() const { return clock_; }

  /// Holds `joint` at `target` (a new target, or moves the joint's one) and re-solves.
  /// Errors: a joint out of range, a root (IK never moves roots), a non-finite target.
  Result<void> hold(int joint, const Vec3& target);
  /// A mouse drag of `joint`: its target is where `ray` (through the cursor) meets the plane
  /// through `anchor` (the joint where the press began) that faces the camera at `eye`; then
  /// hold(). Errors: hold()'s, or a ray that misses the plane (parallel, or pointing away).
  Result<void> drag_joint(int joint, const Ray& ray, const Vec3& eye, const Vec3& anchor);
  /// Lets one joint (or every joint) go back to the clip.
  void let_go(int joint);
  /// Lets every held joint go back to the clip.
  void let_go_all();
  /// The held targets, in the order their joints were first held.
  std::span<const HeldTarget> held() const { return held_; }

  /// Shows the foot-locked clip (true) or the captured one. Errors: no foot-locked clip (the
  /// message of foot_lock_problem()).
  Result<void> set_foot_locked(bool locked);
  /// Whether the foot-locked clip is the one shown.
  bool foot_locked() const { return foot_locked_; }
  /// The foot lock's contacts, trails and metrics, or null when it could not be made.
  const FootLockResult* foot_lock() const { return lock_ ? &*lock_ : nullptr; }
  /// Why there is no foot-locked clip ("no joint named LeftHip"), empty when there is one.
  const std::string& foot_lock_problem() const { return lock_problem_; }

  /// Switches the tree IK solver and re-solves the held targets.
  void set_solver(TreeIkSolverKind solver);
  /// Turns BvhSceneOptions::pin_feet on or off and re-solves.
  void set_pin_feet(bool pin);
  /// Turns drawing the ankles' trails on or off.
  void set_trails(bool trails) { options_.trails = trails; }
  /// The options as given to create() and changed by the three setters above; `foot_locked`
  /// keeps its value from create() (foot_locked() says which clip is shown).
  const BvhSceneOptions& options() const { return options_; }

  /// The joint whose limit is drawn (-1: none).
  void select(int joint) { selected_ = joint >= 0 && joint < skeleton_.joint_count() ? joint : -1; }
  /// The joint whose limit is drawn, or -1 for none.
  int selected() const { return selected_; }

  /// The joint drawn nearest to pixel (x, y) of a width x height view (y down) within
  /// `radius_px`, or -1. Roots count; joints sitting on their parent (zero-length bones, not
  /// drawn) do not. Ties go to the joint nearer the camera.
  int pick_joint(const OrbitCamera& camera, double x, double y, double width, double height,
                 double radius_px) const;

  /// The skeleton the clip animates.
  const Skeleton& skeleton() const { return skeleton_; }
  /// One limit per joint, as IK applies them (given to create(), or made there).
  std::span<const JointLimit> limits() const { return limits_; }
  /// The shown motion (captured or foot-locked).
  const SkeletalMotion& motion() const;
  /// The pose on screen: the clip's frame, then IK toward the held targets (FK run).
  const SkeletonPose& pose() const { return pose_; }
  /// The clip's pose of the frame on screen, before IK.
  const SkeletonPose& clip_pose() const { return clip_pose_; }
  /// What the last solve did; empty while no target is held (or when a solve failed).
  const std::optional<BvhSolveReadout>& last_solve() const { return last_; }
  /// The ankles' path over the clip (leg 0 left, 1 right): captured (`locked` false) or
  /// foot-locked. Empty without a foot lock.
  std::vector<Vec3> foot_trail(int leg, bool locked) const;
  /// Height of the lowest joint over both clips (where the floor is drawn).
  double floor_height() const { return floor_; }
  /// Height of the skeleton at rest (sizes bones, joints and limits in pictures).
  double figure_height() const { return figure_height_; }

  /// Floor grid, trails (orange captured, dark blue locked, contact locks as dots), the skeleton
  /// (bones blue, joints yellow; the selected joint larger, with its limit), held targets (green
  /// dots joined to their joints).
  void describe(DrawList& out) const;
  /// A box around every joint over the whole clip: what the camera frames.
  Eigen::AlignedBox3d focus_bounds() const { return bounds_; }

 private:
  // The tree solvers' settings and workspaces, behind a pointer so this header needs none of
  // the solvers' types.
  struct SolverWorkspaces;

  BvhScene();
  void pose_frame();
  void solve();

  Skeleton skeleton_;
  SkeletalMotion captured_, locked_;
  std::vector<JointLimit> limits_;
  BvhSceneOptions options_;
  PlaybackClock clock_{1, 1.0};
  std::optional<BipedLegs> legs_;
  std::optional<FootLockResult> lock_;
  std::string lock_problem_;
  bool foot_locked_ = false;
  int selected_ = -1;
  std::vector<HeldTarget> held_;
  SkeletonPose pose_, clip_pose_;
  std::vector<Effector> effectors_;
  std::unique_ptr<SolverWorkspaces> workspaces_;
  std::optional<BvhSolveReadout> last_;
  double floor_ = 0.0, figure_height_ = 1.0;
  Eigen::AlignedBox3d bounds_;
  int shown_frame_ = -1;
};

}  // namespace animkit
