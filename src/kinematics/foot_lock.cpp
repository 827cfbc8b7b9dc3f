// Foot locking over a whole clip, as a recipe of named stages: measure the ankles, detect the
// contacts, solve each weighted frame's legs, then measure the result.
#include "animkit/kinematics/foot_lock.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "animkit/core/validation.h"
#include "animkit/kinematics/body_scale.h"
#include "animkit/kinematics/ik_types.h"
#include "animkit/kinematics/two_bone_ik.h"

namespace animkit {

namespace {

constexpr double kCentimetresPerMetre = 100.0;

std::optional<Error> check_motion(const Skeleton& skeleton, const SkeletalMotion& motion) {
  if (motion.joint_count != skeleton.joint_count()) {
    return Error{"foot lock motion has " + std::to_string(motion.joint_count) +
                 " joints but the skeleton " + std::to_string(skeleton.joint_count())};
  }
  const std::size_t n = motion.local_rotations.size();
  if (motion.joint_count <= 0 || n % motion.joint_count != 0 ||
      motion.local_translations.size() != n) {
    return Error{"foot lock motion arrays do not hold whole frames"};
  }
  if (motion.frame_count() < 2) {
    return Error{"foot lock needs at least 2 frames, got " + std::to_string(motion.frame_count())};
  }
  if (!(std::isfinite(motion.frame_time) && motion.frame_time > 0.0)) {
    return Error{"foot lock frame time must be > 0 seconds"};
  }
  // The range of IK targets: a root at 1e300 m gave infinite joint positions and an "IK error"
  // of inf reported as a result.
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& t = motion.local_translations[i];
    if (!is_finite(t) || t.cwiseAbs().maxCoeff() > kMaxTargetCoordinate) {
      return Error{"foot lock motion frame " + std::to_string(i / motion.joint_count) + ", joint " +
                   std::to_string(i % motion.joint_count) + ": translation " + to_string(t) +
                   " is not finite or beyond " + format_number(kMaxTargetCoordinate)};
    }
  }
  return std::nullopt;
}

void size_workspace(const Skeleton& skeleton, FootLockWorkspace& ws) {
  if (static_cast<int>(ws.pose.local_rotations.size()) != skeleton.joint_count()) {
    ws.pose = skeleton_rest_pose(skeleton);
  }
  ws.previous_positions.resize(skeleton.joint_count());
  ws.original_positions.resize(skeleton.joint_count());
  ws.corrections.assign(skeleton.joint_count(), Vec3::Zero());
}

// Largest change of a joint's correction (after - before) since the last frame, which this
// frame's corrections then replace.
double correction_step(const SkeletonPose& pose, FootLockWorkspace& ws) {
  double step = 0.0;
  for (std::size_t j = 0; j < ws.corrections.size(); ++j) {
    const Vec3 correction = pose.global_positions[j] - ws.original_positions[j];
    step = std::max(step, (correction - ws.corrections[j]).norm());
    ws.corrections[j] = correction;
  }
  return step;
}

// Joints whose position the lock can change: a knee moves when its hip turns, so the knees and
// everything below them (parents come first, so one pass marks whole subtrees).
void mark_legs(const Skeleton& skeleton, const BipedLegs& legs, std::vector<std::uint8_t>& in_leg) {
  in_leg.assign(skeleton.joint_count(), 0);
  for (const LegJoints& leg : legs) in_leg[leg.knee] = 1;
  for (int j = 0; j < skeleton.joint_count(); ++j) {
    const int p = skeleton.parents()[j];
    if (p >= 0 && in_leg[p]) in_leg[j] = 1;
  }
}

// Forward of the pelvis from the hips: (left - right) x up, so a body whose left is +X faces +Z.
Vec3 pelvis_forward(const SkeletonPose& pose, const BipedLegs& legs) {
  const Vec3 across = pose.global_positions[legs[0].hip] - pose.global_positions[legs[1].hip];
  const Vec3 forward = across.cross(Vec3::UnitY());
  const double n = forward.norm();
  return n > 0.0 ? Vec3(forward / n) : Vec3::UnitZ();
}

// Largest joint moves (all joints, leg joints) from the previous frame's positions, which
// then become this frame's.
struct Steps {
  double all = 0.0, legs = 0.0;
};
void joint_step(const SkeletonPose& pose, FootLockWorkspace& ws, bool first, Steps& steps) {
  for (std::size_t j = 0; j < ws.previous_positions.size(); ++j) {
    if (!first) {
      const double step = (pose.global_positions[j] - ws.previous_positions[j]).norm();
      steps.all = std::max(steps.all, step);
      if (ws.in_leg[j]) steps.legs = std::max(steps.legs, step);
    }
    ws.previous_positions[j] = pose.global_positions[j];
  }
}

// Stage 1: the original ankle trails, the lowest ankle height and the largest joint step.
double measure_original(const Skeleton& skeleton, const BipedLegs& legs,
                        const SkeletalMotion& motion, FootLockWorkspace& ws,
                        FootLockResult& result) {
  const int frames = motion.frame_count();
  result.ankles_before.resize(static_cast<std::size_t>(frames) * 2);
  double ground = std::numeric_limits<double>::max();
  Steps steps;
  for (int f = 0; f < frames; ++f) {
    motion.read_frame(f, ws.pose);
    skeleton_forward_kinematics(skeleton, ws.pose);
    for (int leg = 0; leg < 2; ++leg) {
      const Vec3& a = ws.pose.global_positions[legs[leg].ankle];
      result.ankles_before[f * 2 + leg] = a;
      ground = std::min(ground, a.y());
    }
    joint_step(ws.pose, ws, f == 0, steps);
  }
  result.metrics.max_joint_step_before_cm = steps.all * kCentimetresPerMetre;
  result.metrics.max_leg_step_before_cm = steps.legs * kCentimetresPerMetre;
  return ground;
}

// The ankle target of one leg: moved along the hip-target line into the distances the knee's
// flexion range allows (law of cosines: d^2 = l1^2 + l2^2 + 2 l1 l2 cos(flexion)). Near the
// longest distance a hard clamp makes the knee snap as a target crosses it (the flexion grows
// like the square root of the distance missing), so from d_soft = max(longest - soft_reach,
// the original ankle's distance d0) on, the distance approaches the longest one exponentially:
// d_soft + s (1 - exp(-(d - d_soft) / s)) with s = longest - d_soft, the same slope as d at
// d_soft. Starting no earlier than d0 keeps the original pose where the weight is 0.
Vec3 leg_target(const Vec3& hip, double l1, double l2, double original_distance, const Vec3& wanted,
                const FootLockSettings& s) {
  const auto reach = [&](double flexion) {
    return std::sqrt(std::max(l1 * l1 + l2 * l2 + 2.0 * l1 * l2 * std::cos(flexion), 0.0));
  };
  const Vec3 d = wanted - hip;
  const double dist = d.norm();
  if (!(dist > 0.0)) return wanted;
  const double shortest = reach(s.max_knee_flexion), longest = reach(s.min_knee_flexion);
  double kept = std::clamp(dist, shortest, longest);
  const double soft_start = std::max(longest - s.soft_reach, original_distance);
  const double soft = longest - soft_start;
  if (soft > 0.0 && dist > soft_start) {
    kept = soft_start + soft * (1.0 - std::exp(-(dist - soft_start) / soft));
  }
  return kept == dist ? wanted : Vec3(hip + d * (kept / dist));
}

// Stage 2 for one leg of one frame: solve hip and knee for the weighted target and write the
// new local rotations (ankle keeps its world orientation). Returns |ankle - wanted target|.
double solve_leg(const Skeleton& skeleton, const LegJoints& leg, const Vec3& lock, double w,
                 const Vec3& forward, const FootLockSettings& s, SkeletonPose& pose) {
  const Vec3 hip = pose.global_positions[leg.hip], knee = pose.global_positions[leg.knee];
  const Vec3 ankle = pose.global_positions[leg.ankle];
  const Vec3 wanted = ankle + w * (lock - ankle);
  const double l1 = (knee - hip).norm(), l2 = (ankle - knee).norm();
  // The knee's own bend direction; a straight leg has none and takes the pelvis' forward.
  const Vec3 axis = ankle - hip;
  Vec3 bend = (knee - hip) - (knee - hip).dot(axis) / std::max(axis.squaredNorm(), 1e-300) * axis;
  bend = bend.norm() > 1e-9 ? Vec3(bend.normalized()) : forward;
  Vec3 pole_dir = bend;
  if (s.knee_pole == KneePole::pelvis_forward) {
    const Vec3 mixed = (1.0 - w) * bend + w * forward;
    pole_dir = mixed.norm() > 1e-9 ? Vec3(mixed.normalized()) : forward;
  }
  TwoBoneInput in{hip, knee, ankle, leg_target(hip, l1, l2, axis.norm(), wanted, s),
                  knee + l1 * pole_dir};
  const auto solved = solve_two_bone(in);
  if (!solved) return (ankle - wanted).norm();  // only on degenerate bones: leave the leg
  const int parent = skeleton.parents()[leg.hip];
  const Quat parent_rotation = parent >= 0 ? pose.global_rotations[parent] : Quat::Identity();
  const Quat hip_rotation = (solved->upper_rotation * pose.global_rotations[leg.hip]).normalized();
  const Quat knee_rotation =
      (solved->lower_rotation * pose.global_rotations[leg.knee]).normalized();
  pose.local_rotations[leg.hip] = (parent_rotation.conjugate() * hip_rotation).normalized();
  pose.local_rotations[leg.knee] = (hip_rotation.conjugate() * knee_rotation).normalized();
  pose.local_rotations[leg.ankle] =
      (knee_rotation.conjugate() * pose.global_rotations[leg.ankle]).normalized();
  return (solved->end - wanted).norm();
}

// Stage 3: sliding of the planted ankles between consecutive frames of a span (XZ, cm).
void measure_sliding(const FootLockResult& r, double& before_mean, double& before_max,
                     double& after_mean, double& after_max) {
  double sum_before = 0.0, sum_after = 0.0;
  int count = 0;
  for (int leg = 0; leg < 2; ++leg) {
    for (const FootContactSpan& span : r.contacts[leg].spans) {
      for (int f = span.first; f < span.last; ++f) {
        const auto slide = [&](const std::vector<Vec3>& a) {
          const Vec3 d = a[(f + 1) * 2 + leg] - a[f * 2 + leg];
          return std::hypot(d.x(), d.z()) * kCentimetresPerMetre;
        };
        const double b = slide(r.ankles_before), a = slide(r.ankles_after);
        sum_before += b;
        sum_after += a;
        before_max = std::max(before_max, b);
        after_max = std::max(after_max, a);
        ++count;
      }
    }
  }
  if (count > 0) {
    before_mean = sum_before / count;
    after_mean = sum_after / count;
  }
}

}  // namespace

Result<FootLockResult> lock_feet(const Skeleton& skeleton, const BipedLegs& legs,
                                 const SkeletalMotion& input, const FootLockSettings& settings,
                                 FootLockWorkspace& ws, SkeletalMotion& output) {
  if (auto error = settings.validate()) return fail(error->message);
  if (auto error = check_motion(skeleton, input)) return fail(error->message);
  const auto start = std::chrono::steady_clock::now();
  size_workspace(skeleton, ws);
  mark_legs(skeleton, legs, ws.in_leg);
  FootLockResult result;
  FootLockMetrics& m = result.metrics;
  const int frames = input.frame_count();

  const double ground = measure_original(skeleton, legs, input, ws, result);
  std::vector<Vec3> trail(frames);
  for (int leg = 0; leg < 2; ++leg) {
    for (int f = 0; f < frames; ++f) trail[f] = result.ankles_before[f * 2 + leg];
    result.contacts[leg] = detect_foot_contacts(trail, input.frame_time, ground, settings);
    m.contacts[leg] = static_cast<int>(result.contacts[leg].spans.size());
    m.planted_frames[leg] = static_cast<int>(
        std::count(result.contacts[leg].planted.begin(), result.contacts[leg].planted.end(), 1));
  }
  // Nothing to lock is a failure with its likely cause, not a run that did nothing: legs of no
  // human length mean a clip in other units than metres (a CMU file read at scale 1 has 14 m
  // legs, and no ankle ever moves slower than the threshold); else the thresholds exclude
  // every frame.
  if (m.contacts[0] + m.contacts[1] == 0) {
    const double leg = rest_leg_length(skeleton, legs);
    char message[512];
    if (leg < kMinLegMetres || leg > kMaxLegMetres) {
      std::snprintf(message, sizeof message,
                    "no foot contact in %d frames: no ankle stays within %g m of the lowest "
                    "ankle height at under %g m/s; the legs are %.3g m long (a person's are "
                    "about %g m): is the clip in metres?",
                    frames, settings.height_threshold, settings.speed_threshold, leg,
                    kTypicalLegMetres);
    } else {
      std::snprintf(message, sizeof message,
                    "no foot contact in %d frames: no ankle stays within %g m of the lowest "
                    "ankle height at under %g m/s for %d frames or more (the height, speed and "
                    "minimum contact settings)",
                    frames, settings.height_threshold, settings.speed_threshold,
                    settings.min_contact_frames);
    }
    return fail(message);
  }

  output.joint_count = input.joint_count;
  output.frame_time = input.frame_time;
  output.local_rotations = input.local_rotations;
  output.local_translations = input.local_translations;
  result.ankles_after.resize(result.ankles_before.size());
  double error_sum = 0.0, correction = 0.0;
  Steps steps;
  int solves = 0;
  for (int f = 0; f < frames; ++f) {
    input.read_frame(f, ws.pose);
    skeleton_forward_kinematics(skeleton, ws.pose);
    const Vec3 forward = pelvis_forward(ws.pose, legs);
    std::copy(ws.pose.global_positions.begin(), ws.pose.global_positions.end(),
              ws.original_positions.begin());
    bool changed = false;
    for (int leg = 0; leg < 2; ++leg) {
      const FootContacts& c = result.contacts[leg];
      if (c.weight[f] <= 0.0) continue;
      const Vec3& lock = c.lock[f];
      const double error =
          solve_leg(skeleton, legs[leg], lock, c.weight[f], forward, settings, ws.pose);
      error_sum += error;
      m.ik_error_max_cm = std::max(m.ik_error_max_cm, error * kCentimetresPerMetre);
      ++solves;
      changed = true;
    }
    if (changed) {
      skeleton_forward_kinematics(skeleton, ws.pose);
      output.write_frame(f, ws.pose);
    }
    for (int leg = 0; leg < 2; ++leg) {
      result.ankles_after[f * 2 + leg] = ws.pose.global_positions[legs[leg].ankle];
    }
    joint_step(ws.pose, ws, f == 0, steps);
    const double step = correction_step(ws.pose, ws);  // frame 0's is no step
    if (f > 0) correction = std::max(correction, step);
  }
  m.max_correction_step_cm = correction * kCentimetresPerMetre;
  m.max_joint_step_after_cm = steps.all * kCentimetresPerMetre;
  m.max_leg_step_after_cm = steps.legs * kCentimetresPerMetre;
  if (solves > 0) m.ik_error_mean_cm = error_sum / solves * kCentimetresPerMetre;
  measure_sliding(result, m.slide_before_mean_cm, m.slide_before_max_cm, m.slide_after_mean_cm,
                  m.slide_after_max_cm);
  const std::chrono::duration<double, std::milli> elapsed =
      std::chrono::steady_clock::now() - start;
  m.ms_per_frame = elapsed.count() / frames;
  return result;
}

}  // namespace animkit
