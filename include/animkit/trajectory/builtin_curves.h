#pragma once
// Built-in curves beyond the lab's five shapes.
#include <vector>

#include "animkit/core/types.h"

namespace animkit {

/// A three-turn spiral on the plane y = 0 (radius 0.1 to 0.6), sampled at 300 equal steps of
/// a parameter that runs as the cube of the angle's: the points crowd near the centre and
/// spread far apart at the rim (spacing coefficient of variation about 1.1), the way the
/// lab's portrait curve leaves its hair sparse. Resampling by arc length evens it out.
std::vector<Vec3> uneven_spiral_targets();

}  // namespace animkit
