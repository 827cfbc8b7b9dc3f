#include "animkit/scene/cloth_drawing.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace animkit {

void describe_cloth(DrawList& out, const ClothModel& model, const ClothState& state,
                    const ClothStyle& style) {
  out.add_ground_grid(style.floor_height, 16, 0.25, 0.5);
  if (style.surface) {
    // Smooth shading: each vertex normal is the area-weighted sum of its triangles' normals.
    std::vector<Vec3> normals(model.particle_count(), Vec3::Zero());
    for (const auto& t : model.triangles) {
      const Vec3 n = (state.position(t[1]) - state.position(t[0]))
                         .cross(state.position(t[2]) - state.position(t[0]));
      for (int k : t) normals[k] += n;
    }
    for (Vec3& n : normals) n = n.norm() > 0.0 ? Vec3(n.normalized()) : Vec3::UnitY();
    for (const auto& t : model.triangles) {
      const Vec3 p[3] = {state.position(t[0]), state.position(t[1]), state.position(t[2])};
      const Vec3 n[3] = {normals[t[0]], normals[t[1]], normals[t[2]]};
      out.add_triangle(p, n, palette::cloth_front, palette::cloth_back);
    }
  }
  if (style.springs) {
    for (const auto& [a, b] : model.springs) {
      out.add_line(state.position(a), state.position(b), palette::spring, 1.0f);
    }
  }
  for (int i = 0; i < model.particle_count(); ++i) {
    if (model.pinned[i]) {
      out.add_point(state.position(i), palette::pinned, 10.0f);
    } else if (style.particles) {
      out.add_point(state.position(i), palette::particle, 4.0f);
    }
  }
}

// How far below its pins a grid cloth is framed, in sides: the sheet hanging straight down
// spans one side, and its springs stretch under its weight. Measured on the lab's cloth
// (k = 100, m = 1, g = 0.3): its lowest point over 20 s is 1.16 sides below the pins. A soft
// cloth hangs lower (k = 10: 1.98 sides) and passes the floor: it is a drawing aid, not a
// collider.
constexpr double kHangingSides = 1.3;

double cloth_floor_height(const GridClothOptions& grid) {
  return grid.height - (kHangingSides + 0.1) * grid.size;
}

Eigen::AlignedBox3d cloth_focus_bounds(const GridClothOptions& grid, const ClothState& state) {
  Eigen::AlignedBox3d box;
  for (Eigen::Index i = 0; i < state.positions.size() / 3; ++i) {
    box.extend(Vec3(state.positions.segment<3>(3 * i)));
  }
  box.extend(Vec3(0.0, grid.height - kHangingSides * grid.size, -0.5 * grid.size));
  box.extend(Vec3(grid.size, grid.height, 0.5 * grid.size));
  return box;
}

namespace {

// The rest shape's box and the lowest point a sheet hanging from its pins reaches (by the
// grid's measure: kHangingSides of its largest side below its lowest pin).
struct Hanging {
  Eigen::AlignedBox3d rest;
  double side = 0.0, bottom = 0.0;
};
Hanging hanging(const ClothDesc& desc) {
  Hanging h;
  double top = std::numeric_limits<double>::infinity();
  for (const ParticleDesc& p : desc.particles) {
    h.rest.extend(p.position);
    if (p.pinned) top = std::min(top, p.position.y());
  }
  if (desc.particles.empty()) return h;
  if (!std::isfinite(top)) top = h.rest.min().y();
  h.side = h.rest.sizes().maxCoeff();
  h.bottom = top - kHangingSides * h.side;
  return h;
}

}  // namespace

double cloth_floor_height(const ClothDesc& desc) {
  const Hanging h = hanging(desc);
  return h.bottom - 0.1 * h.side;
}

Eigen::AlignedBox3d cloth_focus_bounds(const ClothDesc& desc, const ClothState& state) {
  const Hanging h = hanging(desc);
  Eigen::AlignedBox3d box = h.rest;
  for (Eigen::Index i = 0; i < state.positions.size() / 3; ++i) {
    box.extend(Vec3(state.positions.segment<3>(3 * i)));
  }
  if (!h.rest.isEmpty()) box.extend(Vec3(h.rest.center().x(), h.bottom, h.rest.center().z()));
  return box;
}

}  // namespace animkit
