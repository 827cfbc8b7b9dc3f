#pragma once
// The point-cache output of a cloth run: cloth.pc2 (every frame's particle positions, frame 0
// the start) and, when a collider moves, colliders.pc2 (their surface vertices frame by frame,
// where the solver has them): what Blender's Mesh Cache modifier plays back on cloth.obj and
// colliders.obj. Both files are whole at the end of a run that did not diverge, or absent.
#include <Eigen/Geometry>
#include <filesystem>
#include <optional>
#include <string>

#include "animkit/cloth/cloth_run.h"
#include "animkit/io/point_cache.h"

namespace animkit {

struct PointCacheOptions {
  std::string cloth_file = "cloth.pc2";
  /// Whether moving colliders get colliders.pc2.
  bool colliders = true;
  /// Applied to every cloth position before it is written: e.g. into a Blender object's local
  /// space with Blender's axes (Z up).
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  float start_frame = 0.0f;  ///< the files' first frame (Pc2Writer::open)
};

class PointCacheSink final : public ClothSink {
 public:
  explicit PointCacheSink(std::filesystem::path dir, PointCacheOptions options = {})
      : dir_(std::move(dir)), options_(std::move(options)) {}

  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  Result<void> frame(const ClothFrame& frame) override;
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;
  void abandon() override;

 private:
  Result<void> add(const ClothFrame& frame);

  std::filesystem::path dir_;
  PointCacheOptions options_;
  bool transformed_ = false;
  Eigen::VectorXd positions_;  // the transformed frame
  std::optional<Pc2Writer> cloth_, colliders_;
};

}  // namespace animkit
