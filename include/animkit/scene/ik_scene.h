#pragma once
// The interactive "Inverse Kinematics" scene: an arm drawing a list of targets one frame at a
// time, as the lab's app does, plus a free target the user can drag. The viewer and the CLI's
// pictures both drive this class; it holds the state, they only show it.
#include <optional>
#include <span>
#include <vector>

#include "animkit/kinematics/ik_solver.h"
#include "animkit/scene/draw_list.h"
#include "animkit/trajectory/trajectory.h"

namespace animkit {

/// How an IkScene solves: the chain solver and its options.
struct IkSceneOptions {
  /// The chain solver: CCD (the default) or FABRIK.
  IkSolverKind solver = IkSolverKind::ccd;
  IkOptions ik;  ///< lab defaults
};

/// What the last solve did (for the viewer's readouts).
struct IkSolveReadout {
  /// The target solved for, world space.
  Vec3 target = Vec3::Zero();
  /// What the solver reported: iterations, error, convergence, reachability.
  IkResult result;
  /// Wall-clock time of the solve, microseconds.
  double solve_time_us = 0.0;
};

/// One moment of an arm drawing, as describe_arm_drawing() shows it.
struct ArmDrawingView {
  std::span<const Vec3> joints;             ///< the arm's joint positions (world)
  std::span<const Vec3> targets;            ///< every target of the drawing
  std::span<const char> pen_down;           ///< per target (empty: all down)
  std::span<const std::vector<Vec3>> path;  ///< the strokes drawn so far
  std::optional<Vec3> unreachable_target;   ///< the current target, when out of reach
};

/// Describes an arm drawing: ground grid, targets (green; pen-up travel grey), the drawn
/// strokes (red), the arm (bones as boxes, joints as spheres, the pen as a white dot) and an
/// unreachable target (orange, joined to the pen). Shared by IkScene and the CLI's pictures.
void describe_arm_drawing(DrawList& out, const ArmDrawingView& view);

/// The direction pictures of the arm are taken from: high enough to see the drawing plane.
inline constexpr double kIkPictureYaw = 0.5, kIkPicturePitch = 0.9;  ///< pitch, radians

/// The interactive IK scene (see the top of this header): a chain solving for a trajectory's
/// targets one advance() at a time and drawing the path, or following a dragged target. Made
/// by create().
class IkScene {
 public:
  /// Errors: an invalid chain, an empty target list or a non-finite target (naming its index),
  /// a pen list of the wrong size, invalid solver options.
  static Result<IkScene> create(const ChainDesc& chain, Trajectory trajectory,
                                const IkSceneOptions& options = {});

  /// Back to the rest pose, the first target and an empty path.
  void reset();
  /// Solves for the next target and, with the pen down, extends the drawn path. After the last
  /// target the next call starts a new lap: rest pose, empty path (the lab's behaviour).
  const IkSolveReadout& advance();
  /// Solves for any target (a dragged one) from the current pose; the drawn path is untouched.
  /// Errors: a non-finite target.
  Result<IkSolveReadout> follow(const Vec3& target);
  /// Replaces the trajectory and resets. Errors as in create().
  Result<void> set_trajectory(Trajectory trajectory);
  /// Switches the solver for the solves that follow; the pose and the path are kept.
  void set_solver(IkSolverKind solver) { options_.solver = solver; }

  /// The arm, built from the ChainDesc given to create().
  const Chain& chain() const { return chain_; }
  /// The arm's current pose: after the last solve, or the rest pose.
  const Pose& pose() const { return pose_; }
  /// The trajectory's targets (world space), in drawing order.
  const std::vector<Vec3>& targets() const { return trajectory_.targets; }
  /// The trajectory being drawn: its targets and pen flags.
  const Trajectory& trajectory() const { return trajectory_; }
  /// The strokes drawn in this lap, one polyline per pen-down stretch.
  const std::vector<std::vector<Vec3>>& path() const { return path_; }
  /// The options in use (set_solver() changes the solver).
  const IkSceneOptions& options() const { return options_; }
  /// Index of the target the next advance() solves for.
  int next_target() const { return next_; }
  /// True once every target of the current lap has been solved.
  bool lap_finished() const { return next_ == 0 && solved_in_lap_ > 0; }
  /// The last solve, by advance() or follow(); empty after create(), reset() and
  /// set_trajectory().
  const std::optional<IkSolveReadout>& last_solve() const { return last_; }

  /// Describes the scene: ground grid, targets (green), drawn path (red), the arm (bones as
  /// boxes, joints as spheres) and the last target when it was out of reach (orange, joined
  /// to the end effector).
  void describe(DrawList& out) const;
  /// A box around the targets, the root and the arm's current pose: what a picture frames.
  Eigen::AlignedBox3d focus_bounds() const;

 private:
  IkScene(Chain chain, Trajectory trajectory, const IkSceneOptions& options);
  IkSolveReadout solve(const Vec3& target);

  Chain chain_;
  Pose pose_;
  Trajectory trajectory_;
  std::vector<std::vector<Vec3>> path_;
  IkSceneOptions options_;
  int next_ = 0;
  int solved_in_lap_ = 0;
  std::optional<IkSolveReadout> last_;
};

}  // namespace animkit
