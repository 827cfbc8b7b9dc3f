#pragma once
// Access to one vertex of a stacked 3n vector (positions, velocities, forces: vertex i's
// coordinates at 3i, 3i + 1, 3i + 2), shared by the cloth sources.
#include <Eigen/Core>

#include "animkit/core/types.h"

namespace animkit {

/// Vertex i's three coordinates in the stacked vector x.
inline Vec3 at(const Eigen::VectorXd& x, int i) {
  return x.segment<3>(3 * i);
}

}  // namespace animkit
