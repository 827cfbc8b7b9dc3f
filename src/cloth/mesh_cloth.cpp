#include "animkit/cloth/mesh_cloth.h"

#include <string>

#include "animkit/cloth/mesh_edges.h"
#include "animkit/core/validation.h"
#include "membrane_springs.h"
#include "mesh_bending.h"

namespace animkit {

namespace {

std::array<Vec3, 3> corners(const TriangleMesh& mesh, int t) {
  const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
  return {mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]};
}

double area(const std::array<Vec3, 3>& x) {
  return 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
}

// The pins by index and by box, marked on the particles.
std::optional<Error> add_pins(const MeshClothOptions& o, ClothDesc& desc) {
  const int n = static_cast<int>(desc.particles.size());
  for (int pin : o.pins) {
    if (pin < 0 || pin >= n) {
      return Error{"pin " + std::to_string(pin) + " is not a vertex of the mesh (0.." +
                   std::to_string(n - 1) + ")"};
    }
    desc.particles[static_cast<std::size_t>(pin)].pinned = true;
  }
  for (std::size_t b = 0; b < o.pin_boxes.size(); ++b) {
    const Eigen::AlignedBox3d& box = o.pin_boxes[b];
    const std::string name = "pin box " + std::to_string(b) + " from " + to_string(box.min()) +
                             " to " + to_string(box.max());
    if (!is_finite(box.min()) || !is_finite(box.max())) return Error{name + " is not finite"};
    if ((box.min().array() > box.max().array()).any())
      return Error{name + " has a min corner above its max corner"};
    bool any = false;
    for (int i = 0; i < n; ++i) {
      if (box.contains(o.mesh.vertices[static_cast<std::size_t>(i)])) {
        desc.particles[static_cast<std::size_t>(i)].pinned = true;
        any = true;
      }
    }
    if (!any) return Error{name + " holds no vertex of the mesh"};
  }
  return std::nullopt;
}

// The lab's elements: every edge and, across each interior edge, its opposite vertices, one
// stiffness; every particle one mass.
void add_lab_elements(const MeshClothOptions& o, const std::vector<MeshEdge>& edges,
                      ClothDesc& desc) {
  for (ParticleDesc& p : desc.particles) p.mass = o.mass;
  for (const MeshEdge& e : edges) {
    desc.springs.push_back({e.vertices[0], e.vertices[1], -1.0, o.stiffness});
  }
  for (const MeshEdge& e : edges) {
    if (!e.interior()) continue;
    desc.springs.push_back({opposite_vertex(o.mesh, e.triangles[0], e),
                            opposite_vertex(o.mesh, e.triangles[1], e), -1.0, o.stiffness});
  }
}

// A physical sheet (see mesh_cloth.h): area-weighted masses, each triangle's share of stretch
// stiffness on its edges (membrane_springs.h), a Bergou bend per interior edge (mesh_bending.h).
void add_material_elements(const MeshClothOptions& o, const std::vector<MeshEdge>& edges,
                           ClothDesc& desc) {
  const ClothMaterial& m = *o.material;
  const TriangleMesh& mesh = o.mesh;
  for (ParticleDesc& p : desc.particles) p.mass = 0.0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const double share = m.density * area(corners(mesh, static_cast<int>(t))) / 3.0;
    for (int v : mesh.triangles[t]) desc.particles[static_cast<std::size_t>(v)].mass += share;
  }
  // Per triangle, its three edges' stiffness shares, summed per edge.
  std::vector<std::array<double, 3>> shares(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    shares[t] = membrane_spring_stiffness(corners(mesh, static_cast<int>(t)), m, o.warp);
  const auto share_of = [&](int t, const MeshEdge& e) {
    const auto& tri = mesh.triangles[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      if ((a == e.vertices[0] && b == e.vertices[1]) || (a == e.vertices[1] && b == e.vertices[0]))
        return shares[static_cast<std::size_t>(t)][static_cast<std::size_t>(k)];
    }
    return 0.0;
  };
  for (const MeshEdge& e : edges) {
    double k = share_of(e.triangles[0], e);
    if (e.interior()) k += share_of(e.triangles[1], e);
    if (k > 0.0) desc.springs.push_back({e.vertices[0], e.vertices[1], -1.0, k});
  }
  if (m.bending == 0.0) return;
  for (const MeshEdge& e : edges) {
    if (!e.interior()) continue;
    const std::array<int, 4> p{e.vertices[0], e.vertices[1],
                               opposite_vertex(mesh, e.triangles[0], e),
                               opposite_vertex(mesh, e.triangles[1], e)};
    const EdgeBend bend = edge_bend(
        {mesh.vertices[p[0]], mesh.vertices[p[1]], mesh.vertices[p[2]], mesh.vertices[p[3]]},
        m.bending);
    desc.bends.push_back({p, bend.weights, bend.stiffness});
  }
}

Result<ClothDesc> make_unnamed_mesh_cloth(const MeshClothOptions& o) {
  if (auto error = o.mesh.validate()) return fail(error->message);
  if (!is_finite(o.warp) || !(o.warp.norm() > 0.0))
    return fail("the warp direction must be finite and nonzero, got " + to_string(o.warp));
  if (o.material) {
    if (auto error = o.material->validate()) return fail(error->message);
  }
  auto edges = mesh_edges(o.mesh);
  if (!edges) return fail(edges.error().message);
  std::vector<char> used(o.mesh.vertices.size(), 0);
  for (const auto& tri : o.mesh.triangles) {
    for (int v : tri) used[static_cast<std::size_t>(v)] = 1;
  }
  for (std::size_t v = 0; v < used.size(); ++v) {
    if (!used[v]) {
      return fail("mesh vertex " + std::to_string(v) +
                  " is in no triangle (a particle with no area and no springs)");
    }
  }

  ClothDesc desc;
  desc.gravity = o.gravity;
  desc.damping = o.material ? o.material->damping : o.damping;
  for (const Vec3& x : o.mesh.vertices) desc.particles.push_back({x, Vec3::Zero(), 1.0, false});
  if (o.material) {
    add_material_elements(o, *edges, desc);
  } else {
    add_lab_elements(o, *edges, desc);
  }
  desc.triangles = o.mesh.triangles;
  if (auto error = add_pins(o, desc)) return fail(error->message);
  if (auto error = desc.validate()) return fail(error->message);
  return desc;
}

}  // namespace

Result<ClothDesc> make_mesh_cloth(const MeshClothOptions& options) {
  auto cloth = make_unnamed_mesh_cloth(options);
  if (!cloth && !options.source.empty()) return fail(options.source + ": " + cloth.error().message);
  return cloth;
}

}  // namespace animkit
