#pragma once
// One frame of a built cloth world checked by the exact intersection audit
// (intersection_audit.h): the cloth against itself, against every collider's surface where
// contact had it at the frame's end, and above the ground. Shared by the built-in scenes' test
// and the scenes benchmark, so both judge a frame the same way.
#include <string>

#include "animkit/cloth/cloth_world.h"

namespace animkit::audit {

/// What is wrong with `world` at the end of frame `frame` (its simulator having stepped it),
/// or empty: "particle 12 is on or under the ground", "the cloth intersects itself", "the
/// cloth meets ball", or "ball is not where it should be" (a collider's surface that contact
/// moved elsewhere than the collider's own pose at that time). `desc` is the world's
/// description (its ground and time step). Moves each collider to the frame's time.
std::string world_frame_problem(ClothWorld& world, const ClothWorldDesc& desc, int frame);

}  // namespace animkit::audit
