#pragma once
// The meshes of a cloth run as Blender opens them: cloth.obj (the sheet as it starts, vertices in
// the point cache's order) and, with colliders, colliders.obj (each collider's surface where it
// starts, one object each). Written at the end of a run that did not diverge.
#include <filesystem>
#include <string>

#include "animkit/cloth/cloth_run.h"

namespace animkit {

class ObjSink final : public ClothSink {
 public:
  explicit ObjSink(std::filesystem::path dir) : dir_(std::move(dir)) {}

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame&) override { return {}; }
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;

 private:
  std::filesystem::path dir_;
  std::string cloth_, colliders_;
};

}  // namespace animkit
