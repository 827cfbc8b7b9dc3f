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

void MovingObstacles::advance(ContactGeometry& g, ContactPairFinder& finder,
                              const Eigen::VectorXd& x, double radius, double min_separation,
                              std::vector<ContactPair>& pairs) {
  if (settled_) return;
  // The pairs the obstacles' remaining move may bring within `radius` of the cloth at x (the
  // ground never meets an obstacle), then the longest safe fraction of that move.
  if (!finder.gather(g, x, nullptr, radius, std::nullopt, pairs, &end_)) return;  // x not finite
  move_ = end_ - g.obstacle_positions;
  still_.setZero(x.size());
  const double fraction = earliest_contact(g, pairs, x, still_, 0.0, min_separation, &move_);
  if (fraction >= 1.0) {
    g.obstacle_positions = end_;  // exactly: the end pose's vertices, no rounding left over
    poses_ = aims_;
    settled_ = true;
  } else if (fraction > 0.0) {
    g.obstacle_positions += fraction * move_;
  }
}

}  // namespace animkit
