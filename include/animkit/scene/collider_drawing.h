#pragma once
// Colliders in a picture: each surface as lit triangles in its pose at a given time. Shared by
// the scenes the viewer shows and the CLI's pictures.
#include <vector>

#include "animkit/collision/collider.h"
#include "animkit/scene/draw_list.h"

namespace animkit {

struct ColliderStyle {
  Rgba color = palette::collider;  ///< both sides of every collider's triangles
  bool planes = true;              ///< draw planes as their display squares
};

/// Appends every collider's surface at time t (s), world space, as lit triangles. Spheres and
/// capsules are smooth-shaded with their analytic normals; boxes, planes and meshes flat, so
/// their edges stay sharp.
void describe_colliders(DrawList& out, const std::vector<Collider>& colliders, double t,
                        const ColliderStyle& style = {});

}  // namespace animkit
