// `animkit reach`: a BVH character, at one frame, reaches a hand to a target while both feet
// stay planted (kinematics/hand_reach.h), and the reached pose, its metrics and a before/after
// picture are written.
#include "reach_command.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/io/joint_limits_file.h"
#include "animkit/io/reach_report.h"
#include "animkit/io/skeleton_gltf.h"
#include "animkit/kinematics/foot_lock.h"
#include "animkit/kinematics/hand_reach.h"
#include "animkit/kinematics/human_limits.h"
#include "bvh_input.h"
#include "cli_errors.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

struct ReachArgs {
  std::string in, out, hand = "left", limits;
  std::string solver = std::string(to_string(HandReachSettings{}.solver));
  int frame = 0;
  std::vector<double> target;
  double scale = 1.0;
  bool scale_given = false;  ///< else detected from the legs (body_scale.h)
  HandReachSettings settings;
};

// The hand joint: CMU's "lhand" / "rhand", else the names other exporters use.
int find_hand(const Skeleton& skeleton, bool left) {
  const std::array<const char*, 3> names =
      left ? std::array<const char*, 3>{"lhand", "LeftHand", "LeftWrist"}
           : std::array<const char*, 3>{"rhand", "RightHand", "RightWrist"};
  for (const char* name : names) {
    if (const int joint = skeleton.find_joint(name); joint >= 0) return joint;
  }
  return -1;
}

int run(ReachArgs args) {
  const auto solver = parse_tree_ik_solver(args.solver);
  if (!solver) {
    return report_error("unknown solver " + quote_input(args.solver) +
                        " (expected fabrik, ccd, dls or sdls)");
  }
  args.settings.solver = *solver;
  if (auto error = args.settings.validate()) return report_error(error->message);
  if (args.hand != "left" && args.hand != "right") {
    return report_error("--hand must be left or right, got " + quote_input(args.hand));
  }
  const Vec3 target(args.target[0], args.target[1], args.target[2]);
  if (!is_finite(target)) {
    return report_error("--target must be three finite numbers X Y Z (metres), got " +
                        to_string(target));
  }
  auto metric = read_input_clip(args.in, args.scale, args.scale_given);
  if (!metric) return report_error(metric.error().message);
  args.scale = metric->metres_per_unit;
  BvhClip* clip = &metric->clip;
  if (clip->frame_count() == 0) return report_error(args.in + ": the clip has no frames");
  if (args.frame < 0 || args.frame >= clip->frame_count()) {
    return report_error("--frame must be in [0, " + std::to_string(clip->frame_count() - 1) +
                        "] (" + args.in + " has " + std::to_string(clip->frame_count()) +
                        " frames), got " + std::to_string(args.frame));
  }
  const auto skeleton = build_skeleton(clip->skeleton);
  if (!skeleton) return report_error(args.in + ": " + skeleton.error().message);
  const auto legs = find_biped_legs(*skeleton);
  if (!legs) return report_error(args.in + ": " + legs.error().message);
  const int hand = find_hand(*skeleton, args.hand == "left");
  if (hand < 0) {
    return report_error(
        args.in + ": no " + args.hand + " hand (looked for " +
        (args.hand == "left" ? "lhand, LeftHand, LeftWrist" : "rhand, RightHand, RightWrist") +
        ")");
  }

  std::vector<JointLimit> limits;
  std::string limits_label;
  if (args.limits.empty()) {
    // The viewer's defaults too: knees and elbows one-way hinges about the axes this clip
    // bends them about, other joints wide balls (kinematics/human_limits.h).
    limits = human_joint_limits(*skeleton);
    if (auto error = fit_hinge_axes(*skeleton, motion_from_bvh(*clip), limits)) {
      return report_error(error->message);
    }
    limits_label = "default human limits";
  } else {
    const auto set = read_joint_limits_file(args.limits);
    if (!set) return report_error(set.error().message);
    auto bound = bind_joint_limits(*set, skeleton->names());
    if (!bound) return report_error(args.limits + ": " + bound.error().message);
    limits = std::move(*bound);
    limits_label = args.limits;
  }

  std::string no_video;
  auto output = RunOutput::begin(args.out, no_video);
  if (!output) return report_error(output.error().message);

  SkeletonPose pose = skeleton_rest_pose(*skeleton);
  bvh_frame_to_pose(*clip, args.frame, pose);
  skeleton_forward_kinematics(*skeleton, pose);
  const SkeletonPose before = pose;
  const std::array<int, 2> feet{(*legs)[0].ankle, (*legs)[1].ankle};
  const auto result = reach_hand(*skeleton, limits, hand, feet, target, args.settings, pose);
  if (!result) return report_error(args.in + ": " + result.error().message);

  // reached.bvh: the one reached frame, in the file's own units (a still pose to open anywhere);
  // reached.glb: the same pose in metres, with a figure, for glTF viewers.
  BvhClip reached = *clip;
  bvh_pose_to_frame(pose, reached, args.frame);
  reached.motion = Eigen::MatrixXd(reached.motion.row(args.frame));
  if (auto ok = write_skeleton_glb_file(output->dir() / "reached.glb", reached, 1.0); !ok)
    return report_error(ok.error().message);
  if (auto ok = scale_bvh_clip(reached, 1.0 / args.scale); !ok)
    return report_error(ok.error().message);
  if (auto ok = write_bvh_file(output->dir() / "reached.bvh", reached); !ok) {
    return report_error(ok.error().message);
  }
  const std::string hand_name = skeleton->names()[static_cast<std::size_t>(hand)];
  const ReachLabel label{args.in,      args.frame, hand_name, args.solver,
                         limits_label, args.scale, target};
  if (auto ok = write_reach_report(output->dir(), label, *result, *skeleton, before, pose, feet);
      !ok) {
    return report_error(ok.error().message);
  }
  if (auto ok = output->commit(); !ok) return report_error(ok.error().message);

  const HandReachResult& r = *result;
  std::printf("reach: %s\n", metric->description.c_str());
  std::printf(
      "reach: %s frame %d, %s to %s with %s: hand error %.3f cm, foot drift %.4f cm, %d "
      "iterations, %.3f ms\n",
      args.in.c_str(), args.frame, hand_name.c_str(), to_string(target).c_str(),
      args.solver.c_str(), 100.0 * r.hand_error, 100.0 * r.foot_drift, r.ik.iterations, r.solve_ms);
  if (!r.ik.reachable) {
    std::printf(
        "unreachable: the target is farther than the arm and spine reach; wrote the "
        "closest pose\n");
  } else if (!r.reached) {
    std::printf(
        "not reached: the limits (or the iteration cap) stop the hand %.3f cm short; "
        "wrote the closest pose\n",
        100.0 * r.hand_error);
  }
  std::printf("wrote reached.bvh, reached.glb, metrics.json, reach.png to %s\n", args.out.c_str());
  std::printf(
      "reached.glb is in metres (the file's units x %g), +Y up; reached.bvh in the file's "
      "units\n",
      args.scale);
  return 0;
}

}  // namespace

std::function<int()> add_reach_command(CLI::App& app) {
  auto args = std::make_shared<ReachArgs>();
  CLI::App* cmd = app.add_subcommand(
      "reach",
      "A BVH character, at one frame, reaches a hand to a target while both feet stay planted "
      "(root held, joints within limits); writes reached.bvh, reached.glb, metrics.json and "
      "reach.png to "
      "--out.");
  cmd->add_option("--in", args->in, "The BVH clip (legs named Left/RightHip, Knee, Ankle)")
      ->required();
  cmd->add_option("--frame", args->frame, "The frame that reaches (from 0)")->capture_default_str();
  cmd->add_option("--hand", args->hand,
                  "left or right (joint lhand/rhand, LeftHand/RightHand or "
                  "LeftWrist/RightWrist)")
      ->capture_default_str();
  cmd->add_option("--target", args->target,
                  "Where the hand goes: X,Y,Z in metres (world), as ik --target; X Y Z works "
                  "too")
      ->expected(3)
      ->delimiter(',')
      ->allow_extra_args(false)
      ->required();
  CLI::Option* scale = cmd->add_option(
      "--scale", args->scale,
      "Metres per file unit (CMU's BVH: 0.056444); default: told from the legs' length, and "
      "said");
  cmd->add_option("--limits", args->limits,
                  "Joint limits JSON keyed by joint name, degrees (default: human limits, knees "
                  "and elbows hinges fitted to the clip, other joints wide balls)");
  cmd->add_option("--solver", args->solver, "Tree IK solver: fabrik, ccd, dls or sdls")
      ->capture_default_str();
  cmd->add_option("--max-iterations", args->settings.max_iterations, "Iteration cap (>= 1)")
      ->capture_default_str();
  cmd->add_option("--tolerance", args->settings.tolerance,
                  "Reached when hand and feet are within this distance (m, > 0)")
      ->capture_default_str();
  cmd->add_option("--out", args->out,
                  "Folder for reached.bvh, metrics.json and reach.png (created if needed; "
                  "replaced whole when the run ends)")
      ->required();
  return [args, scale] {
    args->scale_given = scale->count() > 0;
    return run(*args);
  };
}

}  // namespace animkit::cli
