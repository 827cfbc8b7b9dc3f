#include "animkit/io/gltf_sink.h"

#include <utility>

#include "animkit/io/atomic_write.h"

namespace animkit {

Result<void> GltfSink::begin(const ClothFrame& start, int frames, double dt) {
  const ClothModel& model = start.simulator.model();
  if (auto problem = cloth_glb_fits(model.particle_count(), frames + 1LL)) {
    return fail(path_.filename().string() + ": " + problem->message);
  }
  animation_ = {};
  animation_.vertex_count = model.particle_count();
  animation_.triangles = model.triangles;
  animation_.frame_time = dt;
  animation_.positions.reserve(3 * static_cast<std::size_t>(model.particle_count()) *
                               (static_cast<std::size_t>(frames) + 1));
  for (const Collider& c : start.colliders) {
    animation_.colliders.push_back({.name = c.name(), .surface = c.model().surface, .poses = {}});
  }
  add(start);
  return {};
}

Result<void> GltfSink::frame(const ClothFrame& frame) {
  add(frame);
  return {};
}

void GltfSink::add(const ClothFrame& frame) {
  const Eigen::VectorXd& x = frame.simulator.state().positions;
  for (Eigen::Index i = 0; i < x.size(); ++i)
    animation_.positions.push_back(static_cast<float>(x[i]));
  for (std::size_t c = 0; c < animation_.colliders.size(); ++c) {
    animation_.colliders[c].poses.push_back(frame.colliders[c].pose());
  }
}

Result<void> GltfSink::finish(const ClothRun& run, const ClothFrame&) {
  // The frames are let go whatever happens: a sink kept after its run holds no copy of it.
  const ClothAnimation animation = std::exchange(animation_, {});
  if (run.divergence) return {};
  auto bytes = cloth_glb(animation);
  if (!bytes) return fail(path_.filename().string() + ": " + bytes.error().message);
  return write_file_atomic(path_, *bytes);
}

}  // namespace animkit
