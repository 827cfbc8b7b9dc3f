#include "cloth_picture_sink.h"

#include "animkit/scene/cloth_drawing.h"
#include "animkit/scene/collider_drawing.h"

namespace animkit::cli {

void ClothPictureSink::describe(const ClothFrame& frame) {
  picture_.clear();
  describe_cloth(picture_, frame.simulator.model(), frame.simulator.state(),
                 {.floor_height = floor_height_});
  describe_colliders(picture_, frame.colliders);
}

Result<void> ClothPictureSink::video_frame(const ClothFrame& frame) {
  if (!pictures_.take_video_frame()) return {};
  describe(frame);
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
    describe(last);
    if (auto ok = pictures_.write_png(*png_, picture_, camera_); !ok) return ok;
  }
  return pictures_.finish_video();
}

}  // namespace animkit::cli
