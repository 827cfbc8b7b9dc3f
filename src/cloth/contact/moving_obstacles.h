#pragma once
// Colliders that move inside the implicit step, keeping IPC's guarantee that no iterate
// intersects anything (Li et al. 2020, section 5, for the cloth's own motion).
//
// Over a substep from t to t + h each collider's surface goes from where it is (its pose at t
// when the last substep got there) to its pose at t + h (or to a target pose a user gave),
// every vertex along the straight line between the two, so the substep's end is intersection-
// free against every collider at t + h. The line search moves the cloth with the obstacles
// fixed (its energy differences stay those of one function); between iterates, at the
// accepted cloth positions x, the obstacles advance along their lines as far as Additive CCD
// (collision/ccd.h) allows with the cloth fixed at x, under the same rule as the cloth's own
// step bound: no pair closer than min_separation of its distance before the advance. Both
// motions start intersection-free and CCD keeps each so, so every iterate is. The barrier then
// pushes the cloth away from where the obstacle now is, the next iterate makes room, and the
// obstacle advances again; the substep is not converged until every obstacle is at its end.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "animkit/collision/collider.h"
#include "contact_candidates.h"

namespace animkit {

class MovingObstacles {
 public:
  /// A collider whose surface's vertices are the obstacles' vertices from `first_vertex` on.
  void add(Collider collider, int first_vertex);

  const std::vector<Collider>& colliders() const { return colliders_; }
  /// From now on, collider i aims at `target` (validated by the caller) instead of its motion.
  void set_target(std::size_t i, const RigidPose& target) { targets_[i] = target; }
  /// The pose collider i last reached (its surface's vertices are exactly there when settled).
  const RigidPose& pose(std::size_t i) const { return poses_[i]; }

  /// Starts a substep ending at time t_end (s): the obstacles' start positions are where they
  /// are, their ends each collider's pose at t_end (or its target).
  void begin_substep(ContactGeometry& geometry, double t_end);
  /// Moves the obstacles toward their ends as far as CCD allows against the cloth at x (3N,
  /// world). `finder` and `pairs` are the contact term's workspaces (overwritten).
  void advance(ContactGeometry& geometry, ContactPairFinder& finder, const Eigen::VectorXd& x,
               double radius, double min_separation, std::vector<ContactPair>& pairs);
  /// Every obstacle at its end.
  bool settled() const { return settled_; }

 private:
  std::vector<Collider> colliders_;
  std::vector<int> first_vertex_;
  std::vector<std::optional<RigidPose>> targets_;
  std::vector<RigidPose> poses_, aims_;  // reached, and aimed at in this substep
  Eigen::VectorXd end_, move_, still_;   // obstacles' ends and remaining move; a zero cloth move
  std::vector<Vec3> surface_;            // one collider's world vertices
  bool settled_ = true;
};

}  // namespace animkit
