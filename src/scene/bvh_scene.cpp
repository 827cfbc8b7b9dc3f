#include "animkit/scene/bvh_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/kinematics/human_limits.h"
#include "animkit/kinematics/ik_types.h"
#include "animkit/scene/skeleton_drawing.h"

namespace animkit {

namespace {

// Every joint of every frame of `motion`, as FK places it, into `box`; returns the lowest
// height seen.
double extend_bounds(const Skeleton& skeleton, const SkeletalMotion& motion,
                     Eigen::AlignedBox3d& box) {
  SkeletonPose pose = skeleton_rest_pose(skeleton);
  double lowest = std::numeric_limits<double>::infinity();
  for (int f = 0; f < motion.frame_count(); ++f) {
    motion.read_frame(f, pose);
    skeleton_forward_kinematics(skeleton, pose);
    for (const Vec3& p : pose.global_positions) {
      box.extend(p);
      lowest = std::min(lowest, p.y());
    }
  }
  return lowest;
}

}  // namespace

struct BvhScene::SolverWorkspaces {
  TreeIkSolvers solvers;
};

BvhScene::BvhScene() : workspaces_(std::make_unique<SolverWorkspaces>()) {}
BvhScene::BvhScene(BvhScene&&) noexcept = default;
BvhScene& BvhScene::operator=(BvhScene&&) noexcept = default;
BvhScene::~BvhScene() = default;

Result<BvhScene> BvhScene::create(Skeleton skeleton, SkeletalMotion motion,
                                  std::vector<JointLimit> limits, const BvhSceneOptions& options) {
  const int joints = skeleton.joint_count();
  if (motion.joint_count != joints) {
    return fail("the motion has " + std::to_string(motion.joint_count) + " joints, the skeleton " +
                std::to_string(joints));
  }
  if (motion.frame_count() < 1 ||
      motion.local_translations.size() != motion.local_rotations.size() ||
      motion.local_rotations.size() != static_cast<std::size_t>(motion.frame_count()) * joints) {
    return fail(
        "the motion has no frame, or its rotations and translations do not fill whole "
        "frames");
  }
  if (!(std::isfinite(motion.frame_time) && motion.frame_time > 0.0)) {
    return fail("the motion's frame time must be > 0 seconds, got " +
                std::to_string(motion.frame_time));
  }
  if (limits.empty()) {
    limits = human_joint_limits(skeleton);
    if (auto error = fit_hinge_axes(skeleton, motion, limits)) return fail(error->message);
  }
  if (static_cast<int>(limits.size()) != joints) {
    return fail("got " + std::to_string(limits.size()) + " joint limits for " +
                std::to_string(joints) + " joints");
  }
  for (int j = 0; j < joints; ++j) {
    if (auto error = validate(limits[j])) {
      return fail("joint " + skeleton.names()[j] + ": " + error->message);
    }
  }

  BvhScene scene;
  scene.options_ = options;
  scene.clock_ = PlaybackClock(motion.frame_count(), motion.frame_time);
  scene.pose_ = skeleton_rest_pose(skeleton);
  scene.clip_pose_ = scene.pose_;
  double low = scene.pose_.global_positions.front().y(), high = low;
  for (const Vec3& p : scene.pose_.global_positions) {
    low = std::min(low, p.y());
    high = std::max(high, p.y());
  }
  scene.figure_height_ = std::max(high - low, 1e-6);

  if (auto legs = find_biped_legs(skeleton); !legs) {
    scene.lock_problem_ = legs.error().message;
  } else if (motion.frame_count() < 2) {
    scene.lock_problem_ = "foot locking needs at least 2 frames";
  } else {
    scene.legs_ = *legs;
    FootLockWorkspace workspace;
    auto result = lock_feet(skeleton, *legs, motion, options.foot_lock, workspace, scene.locked_);
    if (result) {
      scene.lock_ = std::move(*result);
    } else {
      scene.lock_problem_ = result.error().message;
    }
  }
  scene.floor_ = extend_bounds(skeleton, motion, scene.bounds_);
  if (scene.lock_)
    scene.floor_ = std::min(scene.floor_, extend_bounds(skeleton, scene.locked_, scene.bounds_));

  scene.skeleton_ = std::move(skeleton);
  scene.captured_ = std::move(motion);
  scene.limits_ = std::move(limits);
  scene.foot_locked_ = options.foot_locked && scene.lock_.has_value();
  scene.pose_frame();
  return scene;
}

const SkeletalMotion& BvhScene::motion() const {
  return foot_locked_ ? locked_ : captured_;
}

void BvhScene::advance(double seconds) {
  clock_.advance(seconds);
  if (clock_.frame() != shown_frame_) pose_frame();
}

void BvhScene::seek(int frame) {
  clock_.seek(frame);
  pose_frame();
}

void BvhScene::pose_frame() {
  shown_frame_ = clock_.frame();
  motion().read_frame(shown_frame_, clip_pose_);
  skeleton_forward_kinematics(skeleton_, clip_pose_);
  solve();
}

void BvhScene::solve() {
  pose_ = clip_pose_;
  if (held_.empty()) {
    last_.reset();
    return;
  }
  effectors_.clear();
  for (const HeldTarget& held : held_) effectors_.push_back({held.joint, held.position});
  if (options_.pin_feet && legs_) {
    for (const LegJoints& leg : *legs_) {
      const bool held_already = std::any_of(
          held_.begin(), held_.end(), [&](const HeldTarget& h) { return h.joint == leg.ankle; });
      if (!held_already) effectors_.push_back({leg.ankle, clip_pose_.global_positions[leg.ankle]});
    }
  }
  const TreeIkProblem problem{effectors_, limits_};
  const auto start = std::chrono::steady_clock::now();
  const auto result =
      solve_tree_ik(options_.solver, skeleton_, problem, workspaces_->solvers, pose_);
  const auto stop = std::chrono::steady_clock::now();
  if (!result) {
    // hold() refuses what the solvers would; should one fail anyway, the clip's pose shows.
    pose_ = clip_pose_;
    last_.reset();
    return;
  }
  last_ = BvhSolveReadout{*result, static_cast<int>(effectors_.size()),
                          std::chrono::duration<double, std::micro>(stop - start).count()};
}

Result<void> BvhScene::hold(int joint, const Vec3& target) {
  if (joint < 0 || joint >= skeleton_.joint_count()) {
    return fail("no joint " + std::to_string(joint) + " (the skeleton has " +
                std::to_string(skeleton_.joint_count()) + ")");
  }
  if (skeleton_.parents()[joint] < 0) {
    return fail("joint " + skeleton_.names()[joint] +
                " is a root: IK turns joints but never moves a root");
  }
  // What validate_tree_ik refuses is refused here, so a held target never stops solve().
  if (!target.allFinite() || target.cwiseAbs().maxCoeff() > kMaxTargetCoordinate) {
    return fail("the target of " + skeleton_.names()[joint] + " " + to_string(target) +
                " is not finite or beyond 1e9");
  }
  auto it = std::find_if(held_.begin(), held_.end(),
                         [&](const HeldTarget& h) { return h.joint == joint; });
  if (it == held_.end()) {
    held_.push_back({joint, target});
  } else {
    it->position = target;
  }
  solve();
  return {};
}

Result<void> BvhScene::drag_joint(int joint, const Ray& ray, const Vec3& eye, const Vec3& anchor) {
  const Vec3 facing = eye - anchor;
  if (!(facing.norm() > 0.0)) return fail("the camera is at the dragged joint");
  const auto point = intersect_plane(ray, anchor, facing.normalized());
  if (!point) return fail("the cursor's ray misses the drag plane");
  return hold(joint, *point);
}

void BvhScene::let_go(int joint) {
  std::erase_if(held_, [&](const HeldTarget& h) { return h.joint == joint; });
  solve();
}

void BvhScene::let_go_all() {
  held_.clear();
  solve();
}

Result<void> BvhScene::set_foot_locked(bool locked) {
  if (locked && !lock_) return fail(lock_problem_);
  if (locked != foot_locked_) {
    foot_locked_ = locked;
    pose_frame();
  }
  return {};
}

void BvhScene::set_solver(TreeIkSolverKind solver) {
  options_.solver = solver;
  solve();
}

void BvhScene::set_pin_feet(bool pin) {
  options_.pin_feet = pin;
  solve();
}

int BvhScene::pick_joint(const OrbitCamera& camera, double x, double y, double width, double height,
                         double radius_px) const {
  int best = -1;
  double best_distance = radius_px, best_depth = std::numeric_limits<double>::infinity();
  for (int j = 0; j < skeleton_.joint_count(); ++j) {
    if (skeleton_.parents()[j] >= 0 && skeleton_.bone_lengths()[j] < 1e-9) continue;
    const auto pixel = camera.project(pose_.global_positions[j], width, height);
    if (!pixel) continue;
    const double distance = std::hypot(pixel->x() - x, pixel->y() - y);
    const bool nearer = distance < best_distance - 1e-9 ||
                        (distance <= best_distance + 1e-9 && pixel->z() < best_depth);
    if (distance <= radius_px && nearer) {
      best = j;
      best_distance = distance;
      best_depth = pixel->z();
    }
  }
  return best;
}

std::vector<Vec3> BvhScene::foot_trail(int leg, bool locked) const {
  std::vector<Vec3> trail;
  if (!lock_ || leg < 0 || leg > 1) return trail;
  const std::vector<Vec3>& ankles = locked ? lock_->ankles_after : lock_->ankles_before;
  for (std::size_t i = static_cast<std::size_t>(leg); i < ankles.size(); i += 2) {
    trail.push_back(ankles[i]);
  }
  return trail;
}

void BvhScene::describe(DrawList& out) const {
  const double h = figure_height_;
  const double spacing = 0.25 * h;
  const Vec3 centre = bounds_.center();
  const int cells = static_cast<int>(std::ceil(
                        std::max(bounds_.sizes().x(), bounds_.sizes().z()) / spacing + 2.0)) |
                    1;
  DrawList ground;
  ground.add_ground_grid(floor_, cells, spacing, 0.3 * h);
  // The grid is centred on the origin; the clip walks elsewhere, so move it under the clip.
  const Vec3f shift(static_cast<float>(centre.x()), 0.0f, static_cast<float>(centre.z()));
  for (LineSegment line : ground.lines) {
    line.a += shift;
    line.b += shift;
    out.lines.push_back(line);
  }
  if (options_.trails && lock_) {
    for (int leg = 0; leg < 2; ++leg) out.add_polyline(foot_trail(leg, false), kTrailBefore, 4.0f);
    for (int leg = 0; leg < 2; ++leg) {
      out.add_polyline(foot_trail(leg, true), kTrailAfter, 1.5f);
      for (const FootContactSpan& span : lock_->contacts[leg].spans) {
        out.add_point(span.lock, kTrailAfter, 7.0f);
      }
    }
  }
  SkeletonStyle style;
  style.bone_thickness = 0.022 * h;
  style.joint_radius = 0.016 * h;
  describe_skeleton(out, skeleton_, pose_, style);
  for (const HeldTarget& held : held_) {
    out.add_line(pose_.global_positions[held.joint], held.position, palette::target, 2.0f);
    out.add_point(held.position, palette::target, 12.0f);
  }
  if (selected_ >= 0) {
    out.add_sphere(pose_.global_positions[selected_], 1.6 * style.joint_radius, palette::dragged,
                   12, 8);
    double radius = 0.12 * h;
    for (int k = skeleton_.child_begin()[selected_]; k < skeleton_.child_begin()[selected_ + 1];
         ++k) {
      radius = std::max(radius, 0.6 * skeleton_.bone_lengths()[skeleton_.child_list()[k]]);
    }
    describe_joint_limit(out, skeleton_, pose_, selected_, limits_[selected_], radius);
  }
}

}  // namespace animkit
