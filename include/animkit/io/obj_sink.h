#pragma once
// The meshes of a cloth run as Blender opens them: cloth.obj (the sheet as it starts, vertices in
// the point cache's order) and, with colliders, colliders.obj (each collider's surface where it
// starts, one object each). Written at the end of a run that did not diverge.
#include <filesystem>
#include <string>

#include "animkit/cloth/cloth_run.h"

namespace animkit {

/// Writes DIR/cloth.obj and, with colliders, DIR/colliders.obj: the starting meshes.
class ObjSink final : public ClothSink {
 public:
  /// Writes into `dir`.
  explicit ObjSink(std::filesystem::path dir) : dir_(std::move(dir)) {}

  /// Renders the starting sheet and colliders to OBJ text, kept until finish().
  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  /// Does nothing: only the start is written.
  Result<void> frame(const ClothFrame&) override { return {}; }
  /// Writes the files, each atomically, unless the run diverged.
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  std::filesystem::path dir_;
  std::string cloth_, colliders_;
};

}  // namespace animkit
