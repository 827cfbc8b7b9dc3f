#pragma once
// Which contact pairs exist and which are close. Pairs live in one index space: the cloth's
// particles [0, N), then every obstacle vertex. The broad phase (collision/broad_phase.h) finds
// the pairs near a configuration or along a step; continuous collision detection
// (collision/ccd.h) bounds the step for them.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/collision/broad_phase.h"
#include "animkit/collision/ccd.h"
#include "animkit/collision/collision_mesh.h"
#include "animkit/core/result.h"
#include "animkit/core/triangle_mesh.h"
#include "contact_pair.h"

namespace animkit {

struct ContactGeometry {
  CollisionMesh cloth;      ///< the cloth's triangles and edges
  CollisionMesh obstacles;  ///< every obstacle mesh, concatenated
  /// 3 per obstacle vertex, world, m: where the obstacles are now. Fixed during a line search;
  /// moving colliders advance between iterates (moving_obstacles.h).
  Eigen::VectorXd obstacle_positions;
  /// Where the obstacles were at the substep's start (set by the contact term's prepare()).
  Eigen::VectorXd obstacle_start_positions;
  /// How far the collider's material point at each obstacle vertex moves over the substep
  /// (3 per vertex, world, m): the surface's own move from start to end (a sphere's centre:
  /// its move alone, its spin being obstacle_spin's). What friction measures the cloth's
  /// sliding against; zero for fixed meshes.
  Eigen::VectorXd obstacle_motion;
  /// Per obstacle vertex, m: a sphere collider's radius for its centre, the one vertex by
  /// which it takes part in contact (its exact surface, not a tessellation); 0 for the
  /// vertices of meshes. Pairs with a centre carry it as their thickness.
  std::vector<double> obstacle_radius;
  /// Per obstacle mesh: for a sphere, how the substep turns it about its centre, as the
  /// rotation less the identity (its surface point at offset o from the centre moves by the
  /// centre's obstacle_motion plus obstacle_spin o: what friction feels of a spin); else zero.
  std::vector<Eigen::Matrix3d> obstacle_spin;
  std::vector<double> cloth_rest_length2, obstacle_rest_length2;  ///< per edge, squared
  std::vector<int> obstacle_mesh_start;  ///< per obstacle mesh, its first vertex's index
  bool self_contact = true;

  int cloth_vertices() const { return cloth.vertex_count; }
  /// The obstacle mesh (index into ContactObstacles::meshes) that obstacle vertex v belongs to.
  int obstacle_mesh_of(int v) const;
};

/// The primitives of the cloth (its triangles and their edges) and of the obstacles.
/// `sphere_radius`: per obstacle mesh, 0, or the radius of the sphere it stands for (a mesh of
/// the sphere's centre alone, no triangles); empty: all 0.
Result<ContactGeometry> build_contact_geometry(const ClothModel& model,
                                               const std::vector<TriangleMesh>& obstacles,
                                               bool self_contact,
                                               const std::vector<double>& sphere_radius = {});
/// The cloth's edges' rest lengths from `cloth_positions` (the obstacles' are their own).
void set_cloth_rest_lengths(ContactGeometry& geometry, const Eigen::VectorXd& cloth_positions);

/// Gathers contact pairs; keeps its broad phase's work vectors between calls.
class ContactPairFinder {
 public:
  /// Every pair (point-triangle, edge-edge, particle-ground) that is, or on x + t step for
  /// t in [0, 1] may come, within `radius` (m), into `pairs` (in a fixed order). step ==
  /// nullptr: at x only. `obstacle_end` (3 per obstacle vertex) moves the obstacles linearly
  /// from their positions to it over the same t; nullptr: they stay. Pairs sharing a vertex
  /// and pairs of two obstacle primitives are never listed; cloth-cloth pairs only with
  /// self-contact.
  Result<void> gather(const ContactGeometry& geometry, const Eigen::VectorXd& x,
                      const Eigen::VectorXd* step, double radius, std::optional<double> ground,
                      std::vector<ContactPair>& pairs,
                      const Eigen::VectorXd* obstacle_end = nullptr);

 private:
  BroadPhase broad_phase_;
  ContactCandidates candidates_;
  Eigen::VectorXd end_;
};

/// The largest t in (0, 1] such that no pair of `pairs` that comes within `reach` (the contact
/// distance) on the move gets closer than `min_separation` of its distance at x anywhere on
/// x + s step, s in [0, t] (conservative: Additive CCD, and the exact bound for the ground),
/// nor, the ground's aside, within kMinStartGapFraction of `reach` (the smallest gap a start
/// may have; below it computed gaps are rounding): of what lies above that, min_separation.
/// The obstacles move by s obstacle_step (3 per obstacle vertex) at the same time, or stay
/// with nullptr. A pair whose two primitives' swept boxes stay more than `reach` apart is
/// passed over, as the broad phase would not have listed it for this move. `settings` says how
/// pairs are walked (AdditiveCcdSettings::along_separation); its separation fraction and end
/// are this function's. `distance_floor2`, when given, holds per pair a lower bound of its
/// squared distance at x: a pair whose vertices all move too little to take it below
/// `min_separation` of that is passed over without CCD.
double earliest_contact(const ContactGeometry& geometry, const std::vector<ContactPair>& pairs,
                        const Eigen::VectorXd& x, const Eigen::VectorXd& step, double ground,
                        double reach, double min_separation,
                        const Eigen::VectorXd* obstacle_step = nullptr,
                        AdditiveCcdSettings settings = {},
                        const std::vector<double>* distance_floor2 = nullptr);

}  // namespace animkit
