#pragma once
// A cloth cut from any triangle mesh (an OBJ file, a garment panel): particles at the mesh's
// vertices, springs on its edges, bending across its interior edges, pins by vertex index or by
// box. Like the grid (grid_cloth.h), either the lab's per-particle parameters or a physical
// material (material.h), mapped so that the same material behaves the same at any resolution:
// - mass: density x one third of the area of the particle's triangles;
// - stretch: springs on every edge whose stiffnesses give each triangle the material's membrane
//   stiffnesses, C11 = C22 = stretch along the warp and weft and C66 = shear (the grid's
//   lattice mapping, done per triangle; derivation and its limits in membrane_springs.h);
// - bending: across each interior edge, the quadratic bending element of Bergou et al. 2006
//   with cotangent weights and stiffness B / (A0 + A1), which gives 1/2 B / R^2 per unit area
//   on a sheet rolled into a cylinder of radius R (derivation in mesh_bending.h). It rests
//   flat: a curved input mesh is pulled towards flat by its bending stiffness.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/material.h"
#include "animkit/core/triangle_mesh.h"

namespace animkit {

/// How make_mesh_cloth() turns a triangle mesh into a cloth: the mesh, the parameters or a
/// material, and the pins.
struct MeshClothOptions {
  TriangleMesh mesh = {};  ///< the sheet at rest, world space (m with a material); manifold
  /// The lab's parameters, used without a material: mass per particle (> 0, kg or scene units),
  /// stiffness of every spring (> 0, N/m), the dashpot coefficient (>= 0) and gravity along -y.
  /// Springs join the ends of every edge and, across each interior edge, its two opposite
  /// vertices (what the grid's distance-2 springs are to its lines: bending resistance).
  double mass = 1.0;
  double stiffness = 100.0;  ///< k of every spring, > 0, N/m (without a material)
  double damping = 0.2;      ///< the springs' dashpot coefficient, >= 0 (without a material)
  double gravity = 0.3;      ///< along -y, units/s^2 (also with a material: 9.81 for SI)
  /// A physical material: replaces mass, stiffness and damping (see above).
  std::optional<ClothMaterial> material = std::nullopt;
  /// The material's warp direction (world space, any length > 0; default +x), projected onto
  /// each triangle's plane; the weft is perpendicular to it in the plane.
  Vec3 warp = Vec3::UnitX();
  std::vector<int> pins = {};  ///< vertex indices to pin, each in [0, vertex count)
  /// Boxes (world space) pinning every vertex inside them (borders included); each must hold
  /// at least one vertex.
  std::vector<Eigen::AlignedBox3d> pin_boxes = {};
  /// Where the mesh came from, e.g. its OBJ file's path: make_mesh_cloth's errors start with
  /// it ("sheet.obj: mesh edge ... is shared by 3 triangles"). Empty: no prefix.
  std::string source = {};
};

/// The cloth's description. Errors: the mesh's (TriangleMesh::validate, a non-manifold edge, a
/// vertex in no triangle), a pin out of range, an empty or inverted pin box, a zero warp, and
/// whatever ClothDesc::validate() refuses (e.g. a particle mass below kMassRange for a very
/// fine mesh).
Result<ClothDesc> make_mesh_cloth(const MeshClothOptions& options);

}  // namespace animkit
