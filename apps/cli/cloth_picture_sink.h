#pragma once
// The pictures of a cloth run: with --video every frame (up to 60 a second) through ffmpeg,
// and final.png of the last frame in the --out folder. Nothing of a diverged run.
#include <filesystem>
#include <optional>

#include "animkit/cloth/cloth_run.h"
#include "animkit/scene/draw_list.h"
#include "animkit/scene/orbit_camera.h"
#include "picture_output.h"

namespace animkit::cli {

class ClothPictureSink final : public ClothSink {
 public:
  /// `png`: where final.png goes (none without an --out folder).
  ClothPictureSink(PictureOutput& pictures, const OrbitCamera& camera, double floor_height,
                   std::optional<std::filesystem::path> png)
      : pictures_(pictures), camera_(camera), floor_height_(floor_height), png_(std::move(png)) {}

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  void describe(const ClothFrame& frame);
  Result<void> video_frame(const ClothFrame& frame);

  PictureOutput& pictures_;
  OrbitCamera camera_;
  double floor_height_;
  std::optional<std::filesystem::path> png_;
  DrawList picture_;
};

}  // namespace animkit::cli
