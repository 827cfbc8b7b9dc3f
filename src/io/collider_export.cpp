#include "animkit/io/collider_export.h"

#include <algorithm>
#include <sstream>

namespace animkit {

std::string colliders_obj(std::span<const Collider> colliders, double t) {
  std::ostringstream obj;
  obj.precision(9);
  obj << "# animkit colliders at t = " << t << " s: " << colliders.size()
      << " objects; vertex order = colliders.pc2 point order\n";
  std::vector<Vec3> world;
  int first_vertex = 1;  // OBJ indices start at 1 and run on across objects
  for (const Collider& c : colliders) {
    c.world_vertices_at(t, world);
    obj << "o " << c.name() << '\n';
    for (const Vec3& p : world) obj << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
    for (const auto& tri : c.model().surface.triangles) {
      obj << "f " << tri[0] + first_vertex << ' ' << tri[1] + first_vertex << ' '
          << tri[2] + first_vertex << '\n';
    }
    first_vertex += static_cast<int>(world.size());
  }
  return obj.str();
}

int collider_point_count(std::span<const Collider> colliders) {
  std::size_t count = 0;
  for (const Collider& c : colliders) count += c.model().surface.vertices.size();
  return static_cast<int>(count);
}

bool any_collider_moves(std::span<const Collider> colliders) {
  return std::any_of(colliders.begin(), colliders.end(),
                     [](const Collider& c) { return moves(c.model().desc.motion); });
}

Eigen::VectorXd collider_points(std::span<const Collider> colliders, double t) {
  Eigen::VectorXd points(3 * static_cast<Eigen::Index>(collider_point_count(colliders)));
  std::vector<Vec3> world;
  Eigen::Index next = 0;
  for (const Collider& c : colliders) {
    c.world_vertices_at(t, world);
    for (const Vec3& p : world) {
      points.segment<3>(next) = p;
      next += 3;
    }
  }
  return points;
}

Eigen::VectorXd posed_collider_points(std::span<const Collider> colliders) {
  Eigen::VectorXd points(3 * static_cast<Eigen::Index>(collider_point_count(colliders)));
  Eigen::Index next = 0;
  for (const Collider& c : colliders) {
    for (const Vec3& p : c.world_vertices()) {
      points.segment<3>(next) = p;
      next += 3;
    }
  }
  return points;
}

}  // namespace animkit
