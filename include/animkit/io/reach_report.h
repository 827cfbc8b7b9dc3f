#pragma once
// The files `animkit reach --out DIR` writes besides reached.bvh: metrics.json (names are a
// contract, docs/reach.md) and reach.png, the skeleton before and after the reach seen
// from the front and from the side, drawn without OpenGL (line_plot.h).
#include <filesystem>
#include <span>
#include <string>
#include <string_view>

#include "animkit/core/image.h"
#include "animkit/core/result.h"
#include "animkit/kinematics/hand_reach.h"

namespace animkit {

/// What the reach was, for the reports.
struct ReachLabel {
  std::string input;   ///< the BVH file
  int frame = 0;       ///< its frame that reached
  std::string hand;    ///< the hand joint's name
  std::string solver;  ///< "dls", ...
  std::string limits;  ///< the limits file, or a description of the defaults
  double scale = 1.0;  ///< metres per file unit
  Vec3 target = Vec3::Zero();  ///< where the hand was sent, world space (m)
};

/// Width and height of reach.png: the front and side views side by side.
constexpr int kReachViewWidth = 760, kReachPictureHeight = 720;

/// metrics.json: {"input", "frame", "hand", "target_m": [x, y, z], "solver", "limits",
/// "scale", "hand_error_cm", "foot_drift_cm", "root_drift_cm", "iterations", "converged",
/// "reachable", "reached", "solve_ms"}.
std::string reach_metrics_json(const ReachLabel& label, const HandReachResult& result);

/// reach.png's picture: front view (x right, y up) and side view (z right, y up) at one scale,
/// the skeleton before (orange) and after (blue), the target (green cross) and the feet (dots).
Result<Image> reach_picture(const Skeleton& skeleton, const SkeletonPose& before,
                            const SkeletonPose& after, const Vec3& target,
                            std::span<const int> feet);

/// Writes metrics.json and reach.png into `dir`, each atomically.
Result<void> write_reach_report(const std::filesystem::path& dir, const ReachLabel& label,
                                const HandReachResult& result, const Skeleton& skeleton,
                                const SkeletonPose& before, const SkeletonPose& after,
                                std::span<const int> feet);

}  // namespace animkit
