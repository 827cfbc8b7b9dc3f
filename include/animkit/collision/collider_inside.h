#pragma once
// Whether a point is inside a collider's shape (local frame): how a scene whose cloth starts
// inside a collider is refused ("particle 17 starts inside collider 'table'"). Contact needs
// the cloth outside every collider at the start; from there its barrier keeps it outside.
#include "animkit/collision/collider_shape.h"

namespace animkit {

/// Signed distance (m) from a local point to the analytic shape: negative inside, zero on the
/// surface, positive outside (the plane's solid side is y < 0).
double signed_distance(const PlaneShape& shape, const Vec3& local);
double signed_distance(const SphereShape& shape, const Vec3& local);
double signed_distance(const BoxShape& shape, const Vec3& local);
double signed_distance(const CapsuleShape& shape, const Vec3& local);

/// Generalized winding number of a triangle mesh at a point (Jacobson, Kavan & Sorkine-Hornung
/// 2013): the solid angle the mesh subtends, over 4 pi, summed per triangle with the formula of
/// Van Oosterom & Strackee 1983. For a closed outward mesh it is 1 inside and 0 outside; for a
/// mesh with holes it degrades smoothly instead of flipping like a ray-parity count.
double winding_number(const TriangleMesh& mesh, const Vec3& point);

/// Strictly inside the shape: signed distance < 0 for the analytic shapes, winding number
/// > 1/2 for a mesh. Tie rule: a point on an analytic surface is not inside; a point on a
/// mesh's surface has winding number 1/2 up to rounding and may fall on either side, so a
/// caller that needs the cloth clear of a surface checks the distance as well.
bool inside(const ColliderShape& shape, const Vec3& local);

}  // namespace animkit
