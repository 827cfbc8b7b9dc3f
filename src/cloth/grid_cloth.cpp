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
  if (!rotation.coeffs().allFinite() || std::abs(rotation.norm() - 1.0) > 1e-6)
    return Error{"cloth rotation must be a unit quaternion"};
  if (!offset.allFinite() || offset.cwiseAbs().maxCoeff() > kCoordinateRange.max)
    return Error{"cloth offset must be finite and within " + format_number(kCoordinateRange.max)};
  if (material) {
    if (auto error = material->validate()) return error;
    // The smallest and largest values the mapping gives at this resolution.
    const double spacing = size / cells;
    const std::string at = " at " + std::to_string(cells + 1) + " x " + std::to_string(cells + 1) +
                           " particles and " + format_number(size) + " m";
    const double corner_mass = 0.25 * material->density * spacing * spacing;
    if (!kMassRange.contains(corner_mass)) {
      return Error{kMassRange.refusal("the material's particle mass" + at, corner_mass)};
    }
    const double axis = 0.5 * (material->stretch - material->shear);
    if (!kStiffnessRange.contains(axis))
      return Error{kStiffnessRange.refusal("the material's spring stiffness" + at, axis)};
    const double bend = material->bending / (spacing * spacing);
    if (bend > 0.0 && !kStiffnessRange.contains(bend))
      return Error{kStiffnessRange.refusal("the material's bend stiffness" + at, bend)};
  }
  return std::nullopt;
}

namespace {

// The lab's springs: to the neighbours at distance 1 and 2 along both axes and along both
// diagonals, all of one stiffness; every particle of one mass.
void add_lab_elements(const GridClothOptions& o, ClothDesc& desc) {
  const int n = o.cells;
  const auto id = [n](int i, int j) { return grid_index(n, i, j); };
  const auto spring = [&](int a, int b) { desc.springs.push_back({a, b, -1.0, o.stiffness}); };
  // Same particle and spring order as the lab's grid builder.
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      desc.particles[id(i, j)].mass = o.mass;
      if (i > 0) spring(id(i, j), id(i - 1, j));
      if (i > 1) spring(id(i, j), id(i - 2, j));
      if (j > 0) spring(id(i, j), id(i, j - 1));
      if (j > 1) spring(id(i, j), id(i, j - 2));
      if (i > 0 && j > 0) spring(id(i, j), id(i - 1, j - 1));
      if (i > 0 && j < n) spring(id(i, j), id(i - 1, j + 1));
    }
  }
}

// A physical sheet (see material.h for the mapping): area-weighted masses, axis springs
// stretch - shear (half on the border), diagonal springs shear, bends B / s^2 along both axes
// (half on the border).
void add_material_elements(const GridClothOptions& o, ClothDesc& desc) {
  const ClothMaterial& m = *o.material;
  const int n = o.cells;
  const double spacing = o.size / n;
  const auto id = [n](int i, int j) { return grid_index(n, i, j); };
  const auto border = [n](int k) { return k == 0 || k == n; };
  const auto share = [&](int k) { return border(k) ? 0.5 : 1.0; };  // of a row or column
  const double axis = m.stretch - m.shear, bend = m.bending / (spacing * spacing);
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      desc.particles[id(i, j)].mass = m.density * spacing * spacing * share(i) * share(j);
      if (i > 0) desc.springs.push_back({id(i, j), id(i - 1, j), -1.0, axis * share(j)});
      if (j > 0) desc.springs.push_back({id(i, j), id(i, j - 1), -1.0, axis * share(i)});
      if (i > 0 && j > 0) desc.springs.push_back({id(i, j), id(i - 1, j - 1), -1.0, m.shear});
      if (i > 0 && j < n) desc.springs.push_back({id(i, j), id(i - 1, j + 1), -1.0, m.shear});
      if (bend == 0.0) continue;
      if (i > 1)
        desc.bends.push_back(line_bend(id(i - 2, j), id(i - 1, j), id(i, j), bend * share(j)));
      if (j > 1)
        desc.bends.push_back(line_bend(id(i, j - 2), id(i, j - 1), id(i, j), bend * share(i)));
    }
  }
}

}  // namespace

ClothDesc make_grid_cloth(const GridClothOptions& o) {
  ClothDesc desc;
  desc.gravity = o.gravity;
  desc.damping = o.material ? o.material->damping : o.damping;
  if (o.cells < 1) return desc;  // no particles: validate() says so
  const int n = o.cells;
  const double spacing = o.size / n;
  const auto id = [n](int i, int j) { return grid_index(n, i, j); };
  const Vec3 centre(0.5 * o.size, o.height, 0.0);
  const bool placed = o.rotation.coeffs() != Quat::Identity().coeffs() || o.offset != Vec3::Zero();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= n; ++j) {
      Vec3 p(i * spacing, o.height, j * spacing - 0.5 * o.size);
      // Only a placed sheet is transformed, so the lab's positions keep their exact bits.
      if (placed) p = o.rotation * (p - centre) + centre + o.offset;
      desc.particles.push_back({p, Vec3::Zero(), 1.0, false});
    }
  }
  if (o.material) {
    add_material_elements(o, desc);
  } else {
    add_lab_elements(o, desc);
  }
  switch (o.pins) {
    case GridPins::corners:
      desc.particles[id(0, 0)].pinned = true;
      desc.particles[id(0, n)].pinned = true;
      break;
    case GridPins::edge:
      for (int j = 0; j <= n; ++j) desc.particles[id(0, j)].pinned = true;
      break;
    case GridPins::none:
      break;
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      desc.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      desc.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  return desc;
}

}  // namespace animkit
