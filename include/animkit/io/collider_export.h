#pragma once
// Colliders for Blender, next to the cloth's OBJ + PC2: colliders.obj holds every collider's
// surface as its own object, colliders.pc2 their vertices frame by frame (written with
// Pc2Writer), so a moving collider plays back beside the cloth with the Mesh Cache modifier.
#include <span>
#include <string>
#include <vector>

#include "animkit/collision/collider.h"

namespace animkit {

/// Every collider's surface at time t (s) in world space, as OBJ text: one `o <name>` per
/// collider, in order, with its `v` lines and then its triangles' `f` lines (indices count
/// from the file's first vertex). A plane is its display square (two triangles).
std::string colliders_obj(std::span<const Collider> colliders, double t);

/// How many points a colliders.pc2 frame has: every collider's surface vertices.
int collider_point_count(std::span<const Collider> colliders);

/// Whether any collider's motion moves it (collider_motion.h moves()): then colliders.pc2 is
/// written next to colliders.obj.
bool any_collider_moves(std::span<const Collider> colliders);

/// One colliders.pc2 frame for Pc2Writer::add_frame: the world positions at time t (s) of
/// every collider's surface vertices, x, y, z each, concatenated in colliders_obj's vertex
/// order.
Eigen::VectorXd collider_points(std::span<const Collider> colliders, double t);

/// The same frame where the colliders are now (Collider::world_vertices: their poses as set,
/// e.g. where the solver has them), not where their motions put them.
Eigen::VectorXd posed_collider_points(std::span<const Collider> colliders);

}  // namespace animkit
