#include "cloth_picture_sink.h"

#include "animkit/scene/cloth_drawing.h"
#include "animkit/scene/collider_drawing.h"
#include "animkit/scene/orbit_camera.h"

namespace animkit::cli {

namespace {

OrbitCamera camera_for(const ClothPictureFrame& framing, const PictureOutput& pictures) {
  return OrbitCamera::framing(framing.focus, pictures.aspect(), kClothPictureYaw,
                              kClothPicturePitch);
}

}  // namespace

ClothPictureSink::ClothPictureSink(PictureOutput& pictures, const ClothPictureFrame& framing,
                                   std::optional<std::filesystem::path> png)
    : pictures_(pictures),
      framing_(framing),
      camera_(camera_for(framing, pictures)),
      png_(std::move(png)) {}

void ClothPictureSink::describe(const ClothFrame& frame, double floor_height) {
  picture_.clear();
  describe_cloth(picture_, frame.simulator.model(), frame.simulator.state(),
                 {.floor_height = floor_height});
  describe_colliders(picture_, frame.colliders);
}

Result<void> ClothPictureSink::video_frame(const ClothFrame& frame) {
  if (!pictures_.take_video_frame()) return {};
  describe(frame, framing_.floor_height);
  return pictures_.add_video_frame(picture_, camera_);
}

Result<void> ClothPictureSink::begin(const ClothFrame& start, int, double) {
  return video_frame(start);
}

Result<void> ClothPictureSink::frame(const ClothFrame& frame) {
  return video_frame(frame);
}

Result<void> ClothPictureSink::finish(const ClothRun& run, const ClothFrame& last) {
  if (run.divergence) return {};
  if (png_) {
    const ClothPictureFrame end = widened_to_hold(framing_, last.simulator.state());
    describe(last, end.floor_height);
    if (auto ok = pictures_.write_png(*png_, picture_, camera_for(end, pictures_)); !ok) return ok;
  }
  return pictures_.finish_video();
}

}  // namespace animkit::cli
