#include "animkit/cloth/grid_cloth.h"

#include <cmath>
#include <string>

#include "animkit/cloth/parameter_ranges.h"
#include "animkit/core/validation.h"

namespace animkit {

std::optional<Error> GridClothOptions::validate() const {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (cells < 1 || cells > kMaxGridCells) {
    return Error{"grid must have between 1 and " + std::to_string(kMaxGridCells) +
                 " cells per side, got " + std::to_string(cells)};
  }
  if (!positive(size))
    return Error{"cloth size must be positive and finite, got " + format_number(size)};
  if (!std::isfinite(height)) return Error{"cloth height must be finite"};
  if (!kCoordinateRange.contains(size)) return Error{kCoordinateRange.refusal("cloth size", size)};
  if (!kCoordinateRange.contains(height)) {
    return Error{kCoordinateRange.refusal("cloth height", height)};
  }
  if (!kMassRange.contains(mass)) return Error{kMassRange.refusal("mass", mass)};
  if (!kStiffnessRange.contains(stiffness)) {
    return Error{kStiffnessRange.refusal("stiffness", stiffness)};
  }
  if (!kDampingRange.contains(damping)) return Error{kDampingRange.refusal("damping", damping)};
  if (!kGravityRange.contains(gravity)) return Error{kGravityRange.refusal("gravity", gravity)};
  return std::nullopt;
}

ClothDesc make_grid_cloth(const GridClothOptions& o) {
  ClothDesc desc;
  desc.gravity = o.gravity;
  desc.damping = o.damping;
  if (o.cells < 1) return desc;  // no particles: validate() says so
  const int n = o.cells;
  const double spacing = o.size / n;
  const auto id = [n](int i, int j) { return grid_index(n, i, j); };
  const auto spring = [&](int a, int b) { desc.springs.push_back({a, b, -1.0, o.stiffness}); };
  // Same particle and spring order as the lab's grid builder.
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      desc.particles.push_back(
          {Vec3(i * spacing, o.height, j * spacing - 0.5 * o.size), Vec3::Zero(), o.mass, false});
      if (i > 0) spring(id(i, j), id(i - 1, j));
      if (i > 1) spring(id(i, j), id(i - 2, j));
      if (j > 0) spring(id(i, j), id(i, j - 1));
      if (j > 1) spring(id(i, j), id(i, j - 2));
      if (i > 0 && j > 0) spring(id(i, j), id(i - 1, j - 1));
      if (i > 0 && j < n) spring(id(i, j), id(i - 1, j + 1));
    }
  }
  desc.particles[id(0, 0)].pinned = true;
  desc.particles[id(0, n)].pinned = true;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      desc.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      desc.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return desc;
}

}  // namespace animkit
