#pragma once
// The point-cache output of a cloth run: cloth.pc2 (every frame's particle positions, frame 0
// the start) and, when a collider moves, colliders.pc2 (their surface vertices frame by frame,
// where the solver has them): what Blender's Mesh Cache modifier plays back on cloth.obj and
// colliders.obj. Both files are whole at the end of a run that did not diverge, or absent.
#include <filesystem>
#include <optional>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/point_cache.h"

namespace animkit {

class PointCacheSink final : public ClothSink {
 public:
  explicit PointCacheSink(std::filesystem::path dir) : dir_(std::move(dir)) {}

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  Result<void> add(const ClothFrame& frame);

  std::filesystem::path dir_;
  std::optional<Pc2Writer> cloth_, colliders_;
};

}  // namespace animkit
