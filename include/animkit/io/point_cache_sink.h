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

/// What PointCacheSink writes and how it places the positions.
struct PointCacheOptions {
  std::string cloth_file = "cloth.pc2";  ///< the cloth's cache, a file name in the sink's folder
  /// Whether moving colliders get colliders.pc2.
  bool colliders = true;
  /// Applied to every cloth position before it is written: e.g. into a Blender object's local
  /// space with Blender's axes (Z up).
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();
  float start_frame = 0.0f;  ///< the files' first frame (Pc2Writer::open)
};

/// Streams cloth.pc2 (and colliders.pc2 when a collider moves) frame by frame into temporaries
/// that become the files at the end of a run that did not diverge.
class PointCacheSink final : public ClothSink {
 public:
  /// Writes into `dir` as `options` say.
  explicit PointCacheSink(std::filesystem::path dir, PointCacheOptions options = {})
      : dir_(std::move(dir)), options_(std::move(options)) {}

  /// Opens the caches (colliders.pc2 only when options.colliders is set and a collider moves)
  /// and writes frame 0, the start.
  Result<void> begin(const ClothFrame& start, int frames, double dt) override;
  /// Appends the frame's cloth positions (transformed) and posed collider vertices.
  Result<void> frame(const ClothFrame& frame) override;
  /// Renames the caches into place; a diverged run, or a failure, leaves neither file.
  Result<void> finish(const ClothRun& run, const ClothFrame& last) override;
  /// Closes the caches and removes their temporaries.
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
