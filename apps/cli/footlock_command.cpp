// `animkit footlock`: pins a BVH walk's planted feet (kinematics/foot_lock.h) and writes the
// fixed clip, its metrics and a before/after picture.
#include "footlock_command.h"

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>

#include "animkit/core/quote.h"
#include "animkit/core/validation.h"
#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/io/foot_lock_report.h"
#include "animkit/io/skeleton_gltf.h"
#include "animkit/kinematics/foot_lock.h"
#include "bvh_input.h"
#include "cli_errors.h"
#include "footlock_video.h"
#include "run_output.h"

namespace animkit::cli {

namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

struct FootlockArgs {
  std::string in, out, video;
  PictureArgs video_size;  ///< --video-size (only its width and height)
  double scale = 1.0;
  bool scale_given = false;  ///< else detected from the legs (body_scale.h)
  FootLockSettings settings;
  double knee_min_deg = FootLockSettings{}.min_knee_flexion / kRadiansPerDegree;
  double knee_max_deg = FootLockSettings{}.max_knee_flexion / kRadiansPerDegree;
  std::string knee_pole = std::string(to_string(FootLockSettings{}.knee_pole));
};

int run(FootlockArgs args) {
  const auto pole = parse_knee_pole(args.knee_pole);
  if (!pole) {
    return report_error("unknown --knee-pole " + quote_input(args.knee_pole) +
                        " (expected pelvis-forward or original)");
  }
  FootLockSettings& settings = args.settings;
  settings.knee_pole = *pole;
  settings.min_knee_flexion = args.knee_min_deg * kRadiansPerDegree;
  settings.max_knee_flexion = args.knee_max_deg * kRadiansPerDegree;
  if (auto error = settings.validate()) return report_error(error->message);
  auto metric = read_input_clip(args.in, args.scale, args.scale_given);
  if (!metric) return report_error(metric.error().message);
  args.scale = metric->metres_per_unit;
  BvhClip* clip = &metric->clip;
  const auto skeleton = build_skeleton(clip->skeleton);
  if (!skeleton) return report_error(args.in + ": " + skeleton.error().message);
  const auto legs = find_biped_legs(*skeleton);
  if (!legs) return report_error(args.in + ": " + legs.error().message);
  // Opened before the run, so a missing OpenGL or ffmpeg stops it before any file is written.
  std::string video = args.video;
  auto output = RunOutput::begin(args.out, video);
  if (!output) return report_error(output.error().message);
  PictureArgs picture_args = args.video_size;
  picture_args.no_picture = true;  // compare.png is a plot, not a rendering
  picture_args.video = video;
  // BVH files print the frame time rounded (0.0083333 s): 120.0005 fps would be taken every
  // third frame instead of every second one, so a rate this near a whole number is that number.
  double fps = 1.0 / clip->frame_time;
  if (std::abs(fps - std::round(fps)) < 0.01) fps = std::round(fps);
  auto pictures = PictureOutput::open(picture_args, output->has_folder(), fps);
  if (!pictures) return report_error(pictures.error().message);

  const SkeletalMotion motion = motion_from_bvh(*clip);
  FootLockWorkspace workspace;
  SkeletalMotion locked;
  const auto result = lock_feet(*skeleton, *legs, motion, settings, workspace, locked);
  if (!result) {
    return report_error(args.in + ": " + result.error().message + " (" + metric->description +
                        "; --scale sets it)");
  }

  if (auto ok = render_foot_lock_video(*skeleton, motion, locked, *result, *pictures); !ok) {
    return report_error(ok.error().message);
  }
  // fixed.glb in metres (glTF's unit); the fixed clip goes back in the file's own units.
  motion_to_bvh(locked, *clip);
  if (auto ok = write_skeleton_glb_file(output->dir() / "fixed.glb", *clip, 1.0); !ok)
    return report_error(ok.error().message);
  if (auto ok = scale_bvh_clip(*clip, 1.0 / args.scale); !ok)
    return report_error(ok.error().message);
  if (auto ok = write_bvh_file(output->dir() / "fixed.bvh", *clip); !ok) {
    return report_error(ok.error().message);
  }
  const FootLockClip facts{.input = args.in,
                           .frames = motion.frame_count(),
                           .frame_time = motion.frame_time,
                           .metres_per_unit = args.scale,
                           .scale_description = metric->description};
  if (auto ok = write_foot_lock_report(output->dir(), *result, settings, facts); !ok) {
    return report_error(ok.error().message);
  }
  if (auto ok = output->commit(); !ok) return report_error(ok.error().message);

  const FootLockMetrics& m = result->metrics;
  std::printf("footlock: %s\n", metric->description.c_str());
  std::printf(
      "footlock: %d frames, contacts left %d right %d, sliding %.3f -> %.3f cm/frame (max %.3f "
      "-> %.3f), IK error max %.3f cm, %.4f ms/frame\n",
      motion.frame_count(), m.contacts[0], m.contacts[1], m.slide_before_mean_cm,
      m.slide_after_mean_cm, m.slide_before_max_cm, m.slide_after_max_cm, m.ik_error_max_cm,
      m.ms_per_frame);
  std::printf("wrote fixed.bvh, fixed.glb, metrics.json, compare.png to %s\n", args.out.c_str());
  std::printf(
      "fixed.glb is in metres (the file's units x %g), +Y up; fixed.bvh in the file's "
      "units\n",
      args.scale);
  if (!args.video.empty()) std::printf("wrote %s\n", args.video.c_str());
  return 0;
}

}  // namespace

std::function<int()> add_footlock_command(CLI::App& app) {
  auto args = std::make_shared<FootlockArgs>();
  CLI::App* cmd = app.add_subcommand(
      "footlock",
      "Finds where each foot of a BVH walk is planted, pins it there with leg IK (knees "
      "forward, within a flexion range), blends in and out of each contact, and writes "
      "fixed.bvh, fixed.glb (glTF 2.0, in metres), metrics.json and compare.png to --out.");
  cmd->add_option("--in", args->in, "The BVH clip (legs named Left/RightHip, Knee, Ankle)")
      ->required();
  cmd->add_option(
         "--out", args->out,
         "Folder for fixed.bvh, fixed.glb, metrics.json and compare.png (created if needed; "
         "replaced whole when the run ends)")
      ->required();
  cmd->add_option("--video", args->video,
                  "Also render the walk before (orange lines) and after (blue bones) to this "
                  ".mp4 or .gif (needs OpenGL and ffmpeg)");
  add_size_option(*cmd, "--video-size", args->video_size,
                  "Video size in pixels, WIDTHxHEIGHT (default 960x720)");
  CLI::Option* scale = cmd->add_option(
      "--scale", args->scale,
      "Metres per file unit (CMU's BVH: 0.056444); default: told from the legs' length (metres, "
      "centimetres, millimetres, inches or CMU's unit), and said. Thresholds are in metres");
  cmd->add_option("--height", args->settings.height_threshold,
                  "A foot can be planted at most this high (m) above the clip's lowest ankle")
      ->capture_default_str();
  cmd->add_option("--speed", args->settings.speed_threshold,
                  "... and moving at most this fast (m/s)")
      ->capture_default_str();
  cmd->add_option("--min-contact", args->settings.min_contact_frames,
                  "Shorter planted runs are ignored (frames, >= 1)")
      ->capture_default_str();
  cmd->add_option("--merge-gap", args->settings.merge_gap_frames,
                  "Planted runs this few frames apart are one contact (>= 0)")
      ->capture_default_str();
  cmd->add_option("--blend", args->settings.blend_frames,
                  "Frames to blend into and out of each contact (>= 0; 0 snaps)")
      ->capture_default_str();
  cmd->add_option("--knee-min", args->knee_min_deg, "Least knee flexion on solved frames (deg)")
      ->capture_default_str();
  cmd->add_option("--knee-max", args->knee_max_deg, "Most knee flexion on solved frames (deg)")
      ->capture_default_str();
  cmd->add_option("--soft-reach", args->settings.soft_reach,
                  "Near the straight leg's reach, approach it smoothly over this distance (m; 0: "
                  "hard, the knee may snap)")
      ->capture_default_str();
  cmd->add_option("--knee-pole", args->knee_pole,
                  "Where knees point: pelvis-forward or original (the clip's own bend)")
      ->capture_default_str();
  return [args, scale] {
    args->scale_given = scale->count() > 0;
    return run(*args);
  };
}

}  // namespace animkit::cli
