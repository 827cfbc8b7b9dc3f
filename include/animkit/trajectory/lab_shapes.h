#pragma once
// The lab's built-in target trajectories (docs/drawings.md), on the plane y = 0, exactly as
// the lab's starter code samples them (same counts, same index splits between edges).
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "animkit/core/types.h"

namespace animkit {

enum class LabShape {
  circle,    ///< 150 points, radius 0.6, centred on the origin
  square,    ///< 150 points, side 0.4, centred on the origin
  heart,     ///< 150 points, polar r = 0.5 (1 - sin t)
  triangle,  ///< 150 points, right triangle (0,0,0) -> (0.5,0,0) -> (0,0,0.5)
  star,      ///< 400 points, five-pointed star inscribed in radius 0.4
};

/// "circle", "square", "heart", "triangle", "star".
std::string_view to_string(LabShape shape);
std::optional<LabShape> parse_lab_shape(std::string_view name);
/// Every lab shape, in the lab's menu order.
std::span<const LabShape> all_lab_shapes();

/// The shape's targets in drawing order (world space, y = 0).
std::vector<Vec3> lab_shape_targets(LabShape shape);

}  // namespace animkit
