#include "world_audit.h"

#include <variant>

#include "intersection_audit.h"

namespace animkit::audit {

std::string world_frame_problem(ClothWorld& world, const ClothWorldDesc& desc, int frame) {
  const ClothSimulator& sim = world.simulator;
  TriangleMesh cloth{{}, sim.model().triangles};
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    cloth.vertices.push_back(sim.state().position(i));
    if (desc.ground && !(cloth.vertices.back().y() > desc.ground->height))
      return "particle " + std::to_string(i) + " is on or under the ground";
  }
  if (count_self_intersections(cloth) > 0) return "the cloth intersects itself";
  // Each collider's surface as contact had it at the frame's end: its pose at that time (a
  // sphere keeps its first orientation, its spin being friction's business only).
  const Eigen::VectorXd obstacles =
      world.contact ? world.contact->collider_points() : Eigen::VectorXd();
  int first = 0;
  for (Collider& collider : world.colliders) {
    collider.set_time(frame * desc.time_step);
    TriangleMesh surface{{}, collider.model().surface.triangles};
    for (std::size_t i = 0; i < collider.world_vertices().size(); ++i) {
      surface.vertices.push_back(obstacles.segment<3>(3 * (first + static_cast<int>(i))));
      if (!std::holds_alternative<SphereShape>(collider.model().desc.shape) &&
          (surface.vertices.back() - collider.world_vertices()[i]).norm() >= 1e-9)
        return collider.name() + " is not where it should be";
    }
    first += static_cast<int>(surface.vertices.size());
    if (meshes_intersect(cloth, surface)) return "the cloth meets " + collider.name();
  }
  return {};
}

}  // namespace animkit::audit
