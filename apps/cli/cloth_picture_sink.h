#pragma once
// The pictures of a cloth run: with --video every frame (up to 60 a second) through ffmpeg, seen
// by one camera framing the start, and final.png of the last frame in the --out folder, framing
// the start and the end (a sheet that stretched or slid out of the start's box stays whole in
// it). Nothing of a diverged run.
#include <filesystem>
#include <optional>

#include "animkit/cloth/cloth_run.h"
#include "animkit/scene/cloth_scenes.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"
#include "picture_output.h"

namespace animkit::cli {

class ClothPictureSink final : public ClothSink {
 public:
  /// `framing`: what the camera frames at the start (cloth_picture_frame); `png`: where
  /// final.png goes (none without an --out folder).
  ClothPictureSink(PictureOutput& pictures, const ClothPictureFrame& framing,
                   std::optional<std::filesystem::path> png);

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  void describe(const ClothFrame& frame, double floor_height);
  Result<void> video_frame(const ClothFrame& frame);

  PictureOutput& pictures_;
  ClothPictureFrame framing_;
  OrbitCamera camera_;
  std::optional<std::filesystem::path> png_;
  DrawList picture_;
};

}  // namespace animkit::cli
