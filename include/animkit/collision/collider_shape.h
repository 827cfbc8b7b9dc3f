#pragma once
// The shapes a cloth can collide with, as plain data in the collider's local frame. Contact
// treats a box, a capsule and a mesh as the closed triangle mesh collider_surface() makes of
// it, so one point-triangle / edge-edge code path keeps the cloth out of all of them; a sphere
// as itself, its centre and radius (the radius as the thickness of its centre's pairs with the
// cloth's triangles, docs/contact.md "A sphere as itself"); the plane as an analytic
// half-space (the cloth above it means the whole cloth is above it).
#include <variant>

#include "animkit/core/triangle_mesh.h"
#include "animkit/core/types.h"

namespace animkit {

/// The infinite plane y = 0 of the local frame, normal +y: the half-space y < 0 is solid.
struct PlaneShape {
  /// Side of the square drawn and exported in place of the infinite plane, m, > 0, default 10.
  /// No effect on contact.
  double display_size = 10.0;
};

/// A ball centred on the local origin.
struct SphereShape {
  double radius = 0.5;  ///< m, > 0
};

/// A box centred on the local origin, its faces perpendicular to the local axes.
struct BoxShape {
  Vec3 half_extents = Vec3::Constant(0.5);  ///< half the side along local x, y, z; m, each > 0
};

/// The points within `radius` of the segment from (0, -half_length, 0) to (0, half_length, 0):
/// a cylinder along local y capped by two hemispheres.
struct CapsuleShape {
  double radius = 0.25;      ///< m, > 0
  double half_length = 0.5;  ///< half the cylinder's length (between the caps' centres), m, > 0
};

/// Any triangle mesh, local coordinates in m. Closed and outward-oriented (counter-clockwise
/// seen from outside) for inside() to mean anything; contact works with open meshes too.
struct MeshShape {
  TriangleMesh mesh;  ///< local frame, m: a valid mesh, every |coordinate| <= kMaxColliderSize
};

using ColliderShape = std::variant<PlaneShape, SphereShape, BoxShape, CapsuleShape, MeshShape>;

/// Largest size (radius, half extent, half length, display size) a shape accepts, m: beyond
/// it squared lengths in the contact code would lose every digit of a cloth's size.
inline constexpr double kMaxColliderSize = 1e6;

}  // namespace animkit
