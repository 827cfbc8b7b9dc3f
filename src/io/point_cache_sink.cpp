#include "animkit/io/point_cache_sink.h"

#include "animkit/io/collider_export.h"

namespace animkit {

Result<void> PointCacheSink::begin(const ClothFrame& start, int, double) {
  auto cloth = Pc2Writer::open(dir_ / "cloth.pc2", start.simulator.model().particle_count());
  if (!cloth) return fail(cloth.error().message);
  cloth_.emplace(std::move(*cloth));
  if (any_collider_moves(start.colliders)) {
    auto colliders = Pc2Writer::open(dir_ / "colliders.pc2", collider_point_count(start.colliders));
    if (!colliders) return fail(colliders.error().message);
    colliders_.emplace(std::move(*colliders));
  }
  return add(start);
}

Result<void> PointCacheSink::frame(const ClothFrame& frame) {
  return add(frame);
}

Result<void> PointCacheSink::add(const ClothFrame& frame) {
  if (auto ok = cloth_->add_frame(frame.simulator.state().positions); !ok) return ok;
  if (colliders_) return colliders_->add_frame(posed_collider_points(frame.colliders));
  return {};
}

Result<void> PointCacheSink::finish(const ClothRun& run, const ClothFrame&) {
  if (run.divergence) {
    // A diverged run keeps no animation: the writers remove their temporaries.
    cloth_.reset();
    colliders_.reset();
    return {};
  }
  if (auto ok = cloth_->finish(); !ok) return ok;
  if (colliders_) return colliders_->finish();
  return {};
}

}  // namespace animkit
