#pragma once
// Colliders in a picture: each surface as lit triangles in its pose at a given time or as it
// stands, and the contacts the cloth makes. Shared by the scenes the viewer shows and the
// CLI's pictures.
#include <span>
#include <vector>

#include "animkit/cloth/contact.h"
#include "animkit/collision/collider.h"
#include "animkit/scene/draw_list.h"

namespace animkit {

/// How describe_colliders() draws colliders.
struct ColliderStyle {
  Rgba color = palette::collider;  ///< both sides of every collider's triangles
  bool planes = true;              ///< draw planes as their display squares
};

/// Appends every collider's surface at time t (s), world space, as lit triangles. Spheres and
/// capsules are smooth-shaded with their analytic normals; boxes, planes and meshes flat, so
/// their edges stay sharp.
void describe_colliders(DrawList& out, std::span<const Collider> colliders, double t,
                        const ColliderStyle& style = {});
/// The same with each collider as it stands (its current pose and world vertices), however it
/// got there (its motion, or moved by the user).
void describe_colliders(DrawList& out, std::span<const Collider> colliders,
                        const ColliderStyle& style = {});

/// Appends each contact's closest points, the cloth's (palette::contact) and the other side's
/// (palette::contact_other), joined by a line.
void describe_contact_points(DrawList& out, const std::vector<ContactPoint>& points);

}  // namespace animkit
