#include "animkit/io/obj_sink.h"

#include "animkit/io/atomic_write.h"
#include "animkit/io/collider_export.h"
#include "animkit/io/point_cache.h"

namespace animkit {

Result<void> ObjSink::begin(const ClothFrame& start, int, double) {
  cloth_ = cloth_obj(start.simulator.model(), start.simulator.state());
  colliders_.clear();  // a sink may serve one run after another
  if (!start.colliders.empty()) {
    colliders_ = colliders_obj(start.colliders, start.simulator.state().time);
  }
  return {};
}

Result<void> ObjSink::finish(const ClothRun& run, const ClothFrame&) {
  if (run.divergence) return {};
  if (auto ok = write_file_atomic(dir_ / "cloth.obj", cloth_); !ok) return ok;
  if (!colliders_.empty()) return write_file_atomic(dir_ / "colliders.obj", colliders_);
  return {};
}

}  // namespace animkit
