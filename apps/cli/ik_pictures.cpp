#include "ik_pictures.h"

#include <algorithm>

#include "animkit/scene/ik_scene.h"

namespace animkit::cli {

namespace {

// Frame `frame`: its pose, the targets, the strokes its lap has drawn so far, the target
// marked when it was out of reach.
void describe_frame(DrawList& list, const Trajectory& trajectory, const DrawingFrame& frame,
                    std::span<const std::vector<Vec3>> path) {
  std::optional<Vec3> unreachable;
  if (!frame.ik.reachable) unreachable = frame.target;
  list.clear();
  describe_arm_drawing(
      list, {frame.joint_positions, trajectory.targets, trajectory.pen_down, path, unreachable});
}

}  // namespace

Result<void> render_ik_pictures(const Trajectory& trajectory, const DrawingRun& run,
                                PictureOutput& pictures, const std::filesystem::path& out,
                                std::optional<int> picture_frame) {
  if (run.frames.empty()) return {};
  const std::size_t last = static_cast<std::size_t>(std::clamp<long long>(
      picture_frame.value_or(-1) < 0 ? static_cast<long long>(run.frames.size()) - 1
                                     : *picture_frame,
      0, static_cast<long long>(run.frames.size()) - 1));
  // One camera for the whole run, so the video does not jump: it frames the targets and every
  // pose the arm took.
  Eigen::AlignedBox3d bounds;
  for (const Vec3& t : trajectory.targets) bounds.extend(t);
  for (const DrawingFrame& frame : run.frames) {
    for (const Vec3& p : frame.joint_positions) bounds.extend(p);
  }
  const OrbitCamera camera =
      OrbitCamera::framing(bounds, pictures.aspect(), kIkPictureYaw, kIkPicturePitch);
  DrawList list, picture;
  std::vector<std::vector<Vec3>> path;  // the current lap's strokes, up to the frame drawn
  for (std::size_t f = 0; f < run.frames.size(); ++f) {
    const DrawingFrame& frame = run.frames[f];
    const bool same_lap = f > 0 && run.frames[f - 1].lap == frame.lap;
    if (!same_lap) path.clear();
    if (frame.pen_down) {
      if (!same_lap || !run.frames[f - 1].pen_down) path.emplace_back();
      path.back().push_back(frame.end_effector);
    }
    if (pictures.wants_video()) {
      describe_frame(list, trajectory, frame, path);
      if (auto ok = pictures.add_video_frame(list, camera); !ok) return ok;
    }
    if (f == last) describe_frame(picture, trajectory, frame, path);
    if (f >= last && !pictures.wants_video()) break;
  }
  if (auto ok = pictures.finish_video(); !ok) return ok;
  return pictures.write_png(out / "drawing.png", picture, camera);
}

}  // namespace animkit::cli
