#pragma once
// cloth.glb (cloth_gltf.h): the sheet and its colliders with every frame of a run, written at
// the end of a run that did not diverge. The frames are kept in memory until then (about 24
// bytes a vertex and frame once written; 12 while kept).
#include <filesystem>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/cloth_gltf.h"

namespace animkit {

/// Writes cloth.glb at the end of a run that did not diverge, keeping every frame in memory
/// until then.
class GltfSink final : public ClothSink {
 public:
  /// `path`: the file to write, e.g. OUT/cloth.glb.
  explicit GltfSink(std::filesystem::path path) : path_(std::move(path)) {}

  /// Refuses a run whose frames would not fit a .glb (cloth_glb_fits), before it starts.
  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  /// Keeps the frame's positions and collider poses in memory.
  Result<void> frame(const ClothFrame& frame) override;
  /// Writes the file atomically unless the run diverged; drops the kept frames either way.
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;
  /// Drops the kept frames without writing anything.
  void abandon() override { animation_ = {}; }

 private:
  void add(const ClothFrame& frame);

  std::filesystem::path path_;
  ClothAnimation animation_;
};

}  // namespace animkit
