#pragma once
// Colliders that move inside the implicit step, keeping IPC's guarantee that no iterate
// intersects anything (Li et al. 2020, section 5, for the cloth's own motion).
//
// Over a substep from t to t + h each collider's surface goes from where it is (its pose at t
// when the last substep got there) to its pose at t + h (or to a target pose a user gave),
// every vertex along the straight line between the two, so the substep's end is intersection-
// free against every collider at t + h. The line search moves the cloth with the obstacles
// fixed (its energy differences stay those of one function); between iterates the obstacles
// advance along their lines and push the cloth in their way along: every free particle the
// obstacles' move would bring closer than half the contact distance to an obstacle face (over
// the face itself), or near an obstacle vertex (a sphere's centre standing for its surface),
// or across an obstacle edge, gets the part of that face's, vertex's or edge's move along the
// normal (from a vertex: toward the cloth triangle's nearest point) which it lacks to stay
// there (frictionless contact pushes along the normal only), or, when that lets them go less
// far, the obstacle point's whole move (carried with it). Obstacles and cloth
// then move together, linearly, by the largest fraction of both moves at which Additive CCD
// (collision/ccd.h) keeps every pair (obstacle-cloth, cloth-cloth, cloth-ground) at least
// min_separation of its distance before the move: the same rule as the cloth's own step bound,
// so every iterate stays intersection-free. Newton then relaxes the pushed cloth; the substep is
// not converged until every obstacle is at its end.
//
// Without the push the obstacles could only close (1 - min_separation) of each gap per
// iteration while the barrier's Newton step roughly doubles the gap: a collider pushing cloth
// at speed crawled through hundreds of iterations per step.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "animkit/collision/collider.h"
#include "contact_candidates.h"

namespace animkit {

/// The local points by which a collider takes part in contact: a sphere's centre alone, its
/// radius the thickness of the centre's pairs (its exact surface, not a tessellation that a
/// coarse cloth triangle would rest on by many vertices); else its surface's vertices.
const std::vector<Vec3>& contact_vertices(const Collider& collider);
/// A sphere's radius (m); 0 for every other shape.
double contact_radius(const Collider& collider);

class MovingObstacles {
 public:
  /// A collider whose contact_vertices() are the obstacles' vertices from `first_vertex` on,
  /// obstacle mesh `mesh` of the contact geometry.
  void add(Collider collider, int first_vertex, int mesh);

  const std::vector<Collider>& colliders() const { return colliders_; }
  /// From now on, collider i aims at `target` (validated by the caller) instead of its motion.
  void set_target(std::size_t i, const RigidPose& target) { targets_[i] = target; }
  /// The pose collider i last reached (its surface's vertices are exactly there when settled).
  const RigidPose& pose(std::size_t i) const { return poses_[i]; }

  /// Starts a substep ending at time t_end (s): the obstacles' start positions are where they
  /// are, their ends each collider's pose at t_end (or its target).
  void begin_substep(ContactGeometry& geometry, double t_end);
  /// Moves the obstacles toward their ends, and the free particles of x (3N, world) they push,
  /// as far as CCD allows. `radius`: the contact distance (m). `finder` and `pairs` are the
  /// contact term's workspaces (overwritten).
  void advance(ContactGeometry& geometry, ContactPairFinder& finder,
               const std::vector<char>& pinned, std::optional<double> ground, double radius,
               double min_separation, Eigen::VectorXd& x, std::vector<ContactPair>& pairs);
  /// Every obstacle at its end.
  bool settled() const { return settled_; }
  /// Every collider's surface vertices where contact has them now (world, m, 3 each, in the
  /// order of the colliders and their surfaces' vertices): a sphere's about its centre, with
  /// its first orientation.
  Eigen::VectorXd surface_points(const ContactGeometry& geometry) const;
  /// The longest straight move of a collider surface's vertex from its start to its end in
  /// this substep, m (a sphere's spin moves no vertex of its surface).
  double largest_surface_move() const { return largest_surface_move_; }

 private:
  // push_ = what the particles the obstacles' move (move_) brings within `radius` / 2 lack
  // along the normal; carry_ = the whole move of the obstacle point that pushes each of them.
  void push_cloth(const ContactGeometry& geometry, const std::vector<char>& pinned,
                  const Eigen::VectorXd& x, double radius, const std::vector<ContactPair>& pairs);

  std::vector<Collider> colliders_;
  std::vector<int> first_vertex_;
  std::vector<std::optional<RigidPose>> targets_;
  std::vector<RigidPose> poses_, aims_;                // reached, and aimed at in this substep
  std::vector<std::optional<Quat>> surface_rotation_;  // a sphere's surface: never turned
  std::vector<int> mesh_;  // each collider's obstacle mesh (ContactGeometry::obstacle_spin)
  Eigen::VectorXd end_, move_, push_;  // obstacles' ends and remaining move; the cloth's push
  Eigen::VectorXd carry_;  // the same particles moved as the obstacle point that pushes them
  std::vector<ContactPair> carried_pairs_;  // the pairs along the carried move
  std::vector<double> pushed_;         // per particle: the push's length so far
  double largest_surface_move_ = 0.0;
  bool settled_ = true;
};

}  // namespace animkit
