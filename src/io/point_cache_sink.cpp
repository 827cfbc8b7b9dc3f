#include "animkit/io/point_cache_sink.h"

#include "animkit/io/collider_export.h"

namespace animkit {

Result<void> PointCacheSink::begin(const ClothFrame& start, int, double) {
  cloth_.reset();  // a sink may serve one run after another
  colliders_.reset();
  auto cloth = Pc2Writer::open(dir_ / options_.cloth_file, start.simulator.model().particle_count(),
                               options_.start_frame);
  if (!cloth) return fail(cloth.error().message);
  cloth_.emplace(std::move(*cloth));
  transformed_ = !options_.transform.matrix().isIdentity(0.0);
  if (options_.colliders && any_collider_moves(start.colliders)) {
    auto colliders = Pc2Writer::open(dir_ / "colliders.pc2", collider_point_count(start.colliders),
                                     options_.start_frame);
    if (!colliders) return fail(colliders.error().message);
    colliders_.emplace(std::move(*colliders));
  }
  return add(start);
}

Result<void> PointCacheSink::frame(const ClothFrame& frame) {
  return add(frame);
}

Result<void> PointCacheSink::add(const ClothFrame& frame) {
  const Eigen::VectorXd& x = frame.simulator.state().positions;
  if (transformed_) {
    positions_.resize(x.size());
    for (Eigen::Index i = 0; i < x.size(); i += 3)
      positions_.segment<3>(i) = options_.transform * Vec3(x.segment<3>(i));
  }
  if (auto ok = cloth_->add_frame(transformed_ ? positions_ : x); !ok) return ok;
  if (colliders_) return colliders_->add_frame(posed_collider_points(frame.colliders));
  return {};
}

void PointCacheSink::abandon() {
  // The writers remove their temporaries.
  cloth_.reset();
  colliders_.reset();
}

Result<void> PointCacheSink::finish(const ClothRun& run, const ClothFrame&) {
  if (run.divergence) {  // a diverged run keeps no animation
    abandon();
    return {};
  }
  if (auto ok = cloth_->finish(); !ok) {
    abandon();
    return ok;
  }
  cloth_.reset();
  if (colliders_) {
    // The pair whole or not at all: cloth.pc2 goes again if colliders.pc2 cannot follow.
    auto ok = colliders_->finish();
    colliders_.reset();
    if (!ok) {
      std::error_code ignored;
      std::filesystem::remove(dir_ / options_.cloth_file, ignored);
      return ok;
    }
  }
  return {};
}

}  // namespace animkit
