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

struct IkSceneOptions {
  IkSolverKind solver = IkSolverKind::ccd;
  IkOptions ik;  ///< lab defaults
};

/// What the last solve did (for the viewer's readouts).
struct IkSolveReadout {
  Vec3 target = Vec3::Zero();
  IkResult result;
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
inline constexpr double kIkPictureYaw = 0.5, kIkPicturePitch = 0.9;

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
  void set_solver(IkSolverKind solver) { options_.solver = solver; }

  const Chain& chain() const { return chain_; }
  const Pose& pose() const { return pose_; }
  const std::vector<Vec3>& targets() const { return trajectory_.targets; }
  const Trajectory& trajectory() const { return trajectory_; }
  /// The strokes drawn in this lap, one polyline per pen-down stretch.
  const std::vector<std::vector<Vec3>>& path() const { return path_; }
  const IkSceneOptions& options() const { return options_; }
  /// Index of the target the next advance() solves for.
  int next_target() const { return next_; }
  /// True once every target of the current lap has been solved.
  bool lap_finished() const { return next_ == 0 && solved_in_lap_ > 0; }
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
