#include "moving_obstacles.h"

#include <utility>

namespace animkit {

void MovingObstacles::add(Collider collider, int first_vertex) {
  poses_.push_back(collider.pose());
  aims_.push_back(collider.pose());
  colliders_.push_back(std::move(collider));
  first_vertex_.push_back(first_vertex);
  targets_.emplace_back();
}

void MovingObstacles::begin_substep(ContactGeometry& g, double t_end) {
  g.obstacle_start_positions = g.obstacle_positions;  // same size: no allocation after the first
  end_ = g.obstacle_positions;  // fixed meshes end where they are
  for (std::size_t c = 0; c < colliders_.size(); ++c) {
    aims_[c] = targets_[c] ? *targets_[c] : pose_at(colliders_[c].model().desc.motion, t_end);
    const auto& local = colliders_[c].model().surface.vertices;
    for (std::size_t i = 0; i < local.size(); ++i) {
      end_.segment<3>(3 * (first_vertex_[c] + static_cast<Eigen::Index>(i))) =
          aims_[c].to_world(local[i]);
    }
  }
  settled_ = end_ == g.obstacle_positions;
  if (settled_) poses_ = aims_;
}

// The faces' normals and the particles' gaps are taken where the obstacles are now; a
// particle over several faces takes the largest push.
void MovingObstacles::push_cloth(const ContactGeometry& g, const std::vector<char>& pinned,
                                 const Eigen::VectorXd& x, double radius,
                                 const std::vector<ContactPair>& pairs) {
  const int n = g.cloth_vertices();
  push_.setZero(x.size());
  pushed_.assign(static_cast<std::size_t>(n), 0.0);
  const auto obstacle = [&](int v) -> Vec3 {
    return g.obstacle_positions.segment<3>(3 * (v - n));
  };
  const auto moving = [&](int v) -> Vec3 { return move_.segment<3>(3 * (v - n)); };
  for (const ContactPair& pair : pairs) {
    const int p = pair.vertices[0];
    if (pair.kind != ContactKind::point_triangle || p >= n || pair.vertices[1] < n ||
        pinned[static_cast<std::size_t>(p)]) {
      continue;
    }
    const Vec3 a = obstacle(pair.vertices[1]), b = obstacle(pair.vertices[2]),
               c = obstacle(pair.vertices[3]);
    Vec3 normal = (b - a).cross(c - a);
    const double twice_area = normal.norm();
    if (!(twice_area > 0.0)) continue;
    normal /= twice_area;
    const Vec3 e = x.segment<3>(3 * p) - a;
    double gap = e.dot(normal);
    if (gap < 0.0) {
      normal = -normal;
      gap = -gap;
    }
    // Only a particle over the face itself: barycentric coordinates of its projection.
    const Vec3 projected = e - gap * normal;
    const double wb = normal.dot(projected.cross(c - a)) / twice_area;
    const double wc = normal.dot((b - a).cross(projected)) / twice_area;
    if (wb < 0.0 || wc < 0.0 || wb + wc > 1.0) continue;
    // How far the face comes toward p, past what keeps p half the contact distance off it.
    const Vec3 face_move = (1.0 - wb - wc) * moving(pair.vertices[1]) +
                           wb * moving(pair.vertices[2]) + wc * moving(pair.vertices[3]);
    const double lack = face_move.dot(normal) - (gap - 0.5 * radius);
    if (lack > pushed_[static_cast<std::size_t>(p)]) {
      pushed_[static_cast<std::size_t>(p)] = lack;
      push_.segment<3>(3 * p) = lack * normal;
    }
  }
}

void MovingObstacles::advance(ContactGeometry& g, ContactPairFinder& finder,
                              const std::vector<char>& pinned, std::optional<double> ground,
                              double radius, double min_separation, Eigen::VectorXd& x,
                              std::vector<ContactPair>& pairs) {
  if (settled_) return;
  move_ = end_ - g.obstacle_positions;
  // The faces the obstacles' move sweeps close to the cloth, and what they push.
  if (!finder.gather(g, x, nullptr, radius, std::nullopt, pairs, &end_)) return;  // not finite
  push_cloth(g, pinned, x, radius, pairs);
  // Every pair the joint move may bring within `radius`, then its longest safe fraction.
  if (!finder.gather(g, x, &push_, radius, ground, pairs, &end_)) return;
  const double fraction =
      earliest_contact(g, pairs, x, push_, ground.value_or(0.0), min_separation, &move_);
  if (fraction >= 1.0) {
    g.obstacle_positions = end_;  // exactly: the end pose's vertices, no rounding left over
    x += push_;
    poses_ = aims_;
    settled_ = true;
  } else if (fraction > 0.0) {
    g.obstacle_positions += fraction * move_;
    x += fraction * push_;
  }
}

}  // namespace animkit
