#include "animkit/collision/broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>

#include "animkit/core/validation.h"

namespace animkit {

void ContactCandidates::clear() {
  vertex_triangle.clear();
  edge_edge.clear();
  vertex_collider_triangle.clear();
  collider_vertex_triangle.clear();
  edge_collider_edge.clear();
}

std::size_t ContactCandidates::size() const {
  return vertex_triangle.size() + edge_edge.size() + vertex_collider_triangle.size() +
         collider_vertex_triangle.size() + edge_collider_edge.size();
}

namespace {

// Primitive kinds, in the order of their global indices.
enum Kind { kVertex, kEdge, kTriangle, kColliderVertex, kColliderEdge, kColliderTriangle };

std::optional<Error> check_motion(const MeshMotion& motion, const char* name) {
  const Eigen::Index expected = 3 * Eigen::Index{motion.mesh.vertex_count};
  for (const Eigen::VectorXd* positions : {&motion.start, &motion.end}) {
    if (positions->size() != expected) {
      return Error{std::string(name) + " positions have " + std::to_string(positions->size()) +
                   " entries, expected " + std::to_string(expected) + " (3 per vertex)"};
    }
    for (Eigen::Index i = 0; i < positions->size(); ++i) {
      if (!std::isfinite((*positions)[i])) {
        return Error{std::string(name) + " vertex " + std::to_string(i / 3) +
                     " has a non-finite coordinate"};
      }
    }
  }
  return std::nullopt;
}

bool shares_vertex(const std::array<int, 2>& e, const std::array<int, 2>& f) {
  return e[0] == f[0] || e[0] == f[1] || e[1] == f[0] || e[1] == f[1];
}

bool in_triangle(int v, const std::array<int, 3>& t) {
  return v == t[0] || v == t[1] || v == t[2];
}

}  // namespace

Result<void> BroadPhase::find(const MeshMotion& mesh, double radius, ContactCandidates& out,
                              const MeshMotion* collider) {
  out.clear();
  if (!(std::isfinite(radius) && radius >= 0.0)) {
    return fail("broad phase radius must be finite and >= 0, got " + format_number(radius));
  }
  if (auto error = check_motion(mesh, "mesh")) return std::unexpected(*error);
  if (collider != nullptr) {
    if (auto error = check_motion(*collider, "collider")) return std::unexpected(*error);
  }

  // Global primitive indices: [offsets[k], offsets[k + 1]) are the primitives of kind k.
  const CollisionMesh empty;
  const CollisionMesh& other = collider != nullptr ? collider->mesh : empty;
  const std::array<int, 6> counts = {mesh.mesh.vertex_count,
                                     static_cast<int>(mesh.mesh.edges.size()),
                                     static_cast<int>(mesh.mesh.triangles.size()),
                                     other.vertex_count,
                                     static_cast<int>(other.edges.size()),
                                     static_cast<int>(other.triangles.size())};
  std::array<int, 7> offsets{};
  for (int k = 0; k < 6; ++k) offsets[k + 1] = offsets[k] + counts[k];
  const auto kind_of = [&](int primitive) {
    int k = 0;
    while (primitive >= offsets[k + 1]) ++k;
    return k;
  };

  // Swept boxes, inflated by radius / 2 each: boxes overlap when the primitives come closer
  // than the radius (per axis, so certainly in distance).
  boxes_.resize(offsets[6]);
  const auto box_of = [&](const MeshMotion& m, const int* vertices, int n, Box& box) {
    box.lo = box.hi = m.start.segment<3>(3 * vertices[0]);
    for (int i = 0; i < n; ++i) {
      for (const Eigen::VectorXd* x : {&m.start, &m.end}) {
        const Vec3 p = x->segment<3>(3 * vertices[i]);
        box.lo = box.lo.cwiseMin(p);
        box.hi = box.hi.cwiseMax(p);
      }
    }
    box.lo.array() -= 0.5 * radius;
    box.hi.array() += 0.5 * radius;
  };
  for (int side = 0; side < 2; ++side) {
    const MeshMotion* m = side == 0 ? &mesh : collider;
    if (m == nullptr) continue;
    const int base = 3 * side;
    for (int v = 0; v < counts[base]; ++v) box_of(*m, &v, 1, boxes_[offsets[base] + v]);
    for (int e = 0; e < counts[base + 1]; ++e) {
      box_of(*m, m->mesh.edges[e].data(), 2, boxes_[offsets[base + 1] + e]);
    }
    for (int t = 0; t < counts[base + 2]; ++t) {
      box_of(*m, m->mesh.triangles[t].data(), 3, boxes_[offsets[base + 2] + t]);
    }
  }
  if (boxes_.empty()) return {};

  // The grid: origin at the lower corner of everything, cell size from the mean box size.
  Vec3 origin = boxes_[0].lo, top = boxes_[0].hi;
  double mean_size = 0.0;
  for (const Box& box : boxes_) {
    origin = origin.cwiseMin(box.lo);
    top = top.cwiseMax(box.hi);
    mean_size += (box.hi - box.lo).maxCoeff();
  }
  mean_size /= static_cast<double>(boxes_.size());
  const double extent = (top - origin).maxCoeff();
  double cell = mean_size > 0.0 ? mean_size : (extent > 0.0 ? extent : 1.0);
  constexpr double kMaxCellsPerAxis = 1 << 20;  // keeps the 3D cell key below 2^60
  while (extent / cell > kMaxCellsPerAxis) cell *= 2.0;
  std::array<std::int64_t, 3> dims{};
  const auto cell_coordinate = [&](double x, int axis) {
    const auto c = static_cast<std::int64_t>(std::floor((x - origin[axis]) / cell));
    return std::clamp<std::int64_t>(c, 0, dims[axis] - 1);
  };
  const auto key = [&](std::int64_t i, std::int64_t j, std::int64_t k) {
    return static_cast<std::uint64_t>((i * dims[1] + j) * dims[2] + k);
  };
  // Coarsen while the boxes would fill more than 16 cells each on average.
  const std::uint64_t budget = 16 * boxes_.size() + 64;
  while (true) {
    for (int a = 0; a < 3; ++a) {
      dims[a] = static_cast<std::int64_t>(std::floor((top[a] - origin[a]) / cell)) + 1;
    }
    std::uint64_t total = 0;
    for (const Box& box : boxes_) {
      std::uint64_t n = 1;
      for (int a = 0; a < 3; ++a) {
        n *= static_cast<std::uint64_t>(cell_coordinate(box.hi[a], a) -
                                        cell_coordinate(box.lo[a], a) + 1);
      }
      total += n;
      if (total > budget) break;
    }
    if (total <= budget) break;
    cell *= 2.0;
  }

  entries_.clear();
  for (int p = 0; p < static_cast<int>(boxes_.size()); ++p) {
    const Box& box = boxes_[p];
    for (auto i = cell_coordinate(box.lo.x(), 0); i <= cell_coordinate(box.hi.x(), 0); ++i) {
      for (auto j = cell_coordinate(box.lo.y(), 1); j <= cell_coordinate(box.hi.y(), 1); ++j) {
        for (auto k = cell_coordinate(box.lo.z(), 2); k <= cell_coordinate(box.hi.z(), 2); ++k) {
          entries_.push_back({key(i, j, k), p});
        }
      }
    }
  }
  std::sort(entries_.begin(), entries_.end());

  const CollisionMesh& self = mesh.mesh;
  for (std::size_t begin = 0; begin < entries_.size();) {
    std::size_t end = begin;
    while (end < entries_.size() && entries_[end].cell == entries_[begin].cell) ++end;
    for (std::size_t i = begin; i < end; ++i) {
      const int a = entries_[i].primitive, kind_a = kind_of(a);
      for (std::size_t j = i + 1; j < end; ++j) {
        const int b = entries_[j].primitive, kind_b = kind_of(b);  // a < b, kind_a <= kind_b
        const bool wanted = (kind_a == kVertex && kind_b == kTriangle) ||
                            (kind_a == kEdge && kind_b == kEdge) ||
                            (kind_a == kVertex && kind_b == kColliderTriangle) ||
                            (kind_a == kTriangle && kind_b == kColliderVertex) ||
                            (kind_a == kEdge && kind_b == kColliderEdge);
        if (!wanted) continue;
        const Box &box_a = boxes_[a], &box_b = boxes_[b];
        if ((box_a.lo.array() > box_b.hi.array()).any() ||
            (box_b.lo.array() > box_a.hi.array()).any()) {
          continue;
        }
        // Report from the cell of the intersection's lower corner only (it is in both boxes'
        // cells, so exactly one shared cell qualifies).
        const Vec3 corner = box_a.lo.cwiseMax(box_b.lo);
        if (key(cell_coordinate(corner.x(), 0), cell_coordinate(corner.y(), 1),
                cell_coordinate(corner.z(), 2)) != entries_[begin].cell) {
          continue;
        }
        const int ia = a - offsets[kind_a], ib = b - offsets[kind_b];
        if (kind_b == kTriangle) {
          if (!in_triangle(ia, self.triangles[ib])) out.vertex_triangle.push_back({ia, ib});
        } else if (kind_b == kEdge) {
          if (!shares_vertex(self.edges[ia], self.edges[ib])) out.edge_edge.push_back({ia, ib});
        } else if (kind_b == kColliderTriangle) {
          out.vertex_collider_triangle.push_back({ia, ib});
        } else if (kind_b == kColliderVertex) {
          out.collider_vertex_triangle.push_back({ib, ia});
        } else {
          out.edge_collider_edge.push_back({ia, ib});
        }
      }
    }
    begin = end;
  }
  std::sort(out.vertex_triangle.begin(), out.vertex_triangle.end());
  std::sort(out.edge_edge.begin(), out.edge_edge.end());
  std::sort(out.vertex_collider_triangle.begin(), out.vertex_collider_triangle.end());
  std::sort(out.collider_vertex_triangle.begin(), out.collider_vertex_triangle.end());
  std::sort(out.edge_collider_edge.begin(), out.edge_collider_edge.end());
  return {};
}

}  // namespace animkit
