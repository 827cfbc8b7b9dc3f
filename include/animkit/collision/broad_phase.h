#pragma once
// Broad phase of contact: the point-triangle and edge-edge pairs whose distance may fall below a
// radius (IPC's dhat for the barrier, or dhat plus the step's motion for CCD; Li et al. 2020,
// section 5), found with a uniform spatial hash (Teschner et al., "Optimized Spatial Hashing for
// Collision Detection of Deformable Objects", VMV 2003).
//
// Each primitive gets an axis-aligned box around its positions at t = 0 and t = 1 (so it holds
// the primitive over the whole linear motion), inflated by radius / 2: if two primitives come
// closer than the radius, their boxes overlap. The mesh's boxes are entered in the cells of a
// uniform grid (cell size: their mean size, doubled while the boxes would fill more than 16
// cells each on average), the entries sorted by cell, and the self pairs sharing a cell whose
// boxes overlap reported from the one cell holding the lower corner of the boxes' intersection
// (so once, without a global de-duplication). The collider's boxes go into box trees
// (box_tree.h) that each mesh box is looked up in: a finely tessellated collider's many small
// boxes would crowd the cells sized for the mesh's, and each mesh box would be tested against
// all of them. The trees are kept between queries and refitted, which a rigid collider's
// motion leaves as tight as built. Either way the pairs are exactly those whose boxes overlap.
// Cost: near linear in the number of primitives plus candidates (radix sorts of the cell
// entries and of the pairs). Output sorted, so deterministic. One thread: collecting the cells'
// pairs over two gained nothing measurable on a 41 x 41 drape, and beside another busy process
// each query could wait for a preempted worker.
//
// Self pairs that share a vertex (a vertex and its own triangles, edges with a common end) are
// never reported: their distance is zero by construction and IPC does not treat them as contact.
#include <Eigen/Core>
#include <array>
#include <compare>
#include <cstdint>
#include <vector>

#include "animkit/collision/box_tree.h"
#include "animkit/collision/collision_mesh.h"
#include "animkit/core/result.h"
#include "animkit/core/types.h"

namespace animkit {

/// A vertex and a triangle whose distance may fall below the radius. The ContactCandidates list
/// holding the pair says which mesh (the cloth's or the collider's) each index refers to.
struct VertexTriangleCandidate {
  int vertex = 0;    ///< vertex index, >= 0
  int triangle = 0;  ///< triangle index, >= 0 (in self pairs, never a triangle of the vertex)
  /// Lexicographic order (vertex, then triangle), used to sort the candidate lists.
  auto operator<=>(const VertexTriangleCandidate&) const = default;
};

/// Two edges whose distance may fall below the radius; self pairs never share a vertex.
struct EdgeEdgeCandidate {
  int edge_a = 0;  ///< edge index in the first mesh
  int edge_b = 0;  ///< edge index in the second mesh (> edge_a for self pairs)
  /// Lexicographic order (edge_a, then edge_b), used to sort the candidate lists.
  auto operator<=>(const EdgeEdgeCandidate&) const = default;
};

/// Candidate pairs, each list sorted. Indices are into CollisionMesh::edges / triangles and the
/// vertices of the mesh named in the field.
struct ContactCandidates {
  std::vector<VertexTriangleCandidate> vertex_triangle;           ///< mesh vertex, mesh triangle
  std::vector<EdgeEdgeCandidate> edge_edge;                       ///< mesh edge, mesh edge
  std::vector<VertexTriangleCandidate> vertex_collider_triangle;  ///< mesh vertex, collider tri
  std::vector<VertexTriangleCandidate> collider_vertex_triangle;  ///< collider vertex, mesh tri
  std::vector<EdgeEdgeCandidate> edge_collider_edge;              ///< mesh edge, collider edge

  /// Empties all five lists (keeping their capacity).
  void clear();
  /// The number of candidates in all five lists together.
  std::size_t size() const;
};

namespace broad_phase_detail {
/// A primitive's swept, inflated box (world space).
using Box = AlignedBox;
/// The grid cells a box overlaps: [lo[a], hi[a]] along each axis a.
struct CellSpan {
  std::array<int, 3> lo;  ///< first cell coordinate per axis
  std::array<int, 3> hi;  ///< last cell coordinate per axis
};

/// A primitive (global index over both meshes' vertices, edges, triangles) in a grid cell.
struct CellEntry {
  std::uint64_t cell;  ///< linear index (i * ny + j) * nz + k of the grid cell (i, j, k)
  int primitive;       ///< global primitive index: the box's index in the box list
  /// Lexicographic order (cell, then primitive).
  auto operator<=>(const CellEntry&) const = default;
};
}  // namespace broad_phase_detail

/// A mesh and its vertices' positions at the start and the end of a linear motion: 3 doubles per
/// vertex (x0 y0 z0 x1 ...), world space. For one configuration pass the same vector twice.
struct MeshMotion {
  const CollisionMesh& mesh;     ///< the mesh's edges and triangles
  const Eigen::VectorXd& start;  ///< positions at t = 0, 3 * mesh.vertex_count entries
  const Eigen::VectorXd& end;    ///< positions at t = 1, 3 * mesh.vertex_count entries
  /// Per vertex, m, >= 0: how far the primitive reaches around the vertex (a sphere's centre
  /// stands for the whole sphere); its primitives' boxes grow by it. nullptr: all 0.
  const std::vector<double>* vertex_radius = nullptr;
};

/// The spatial hash. Keeps its work vectors between calls: reuse one object per simulation so a
/// query allocates nothing once the vectors have grown to the scene's size.
class BroadPhase {
 public:
  /// Fills `out` (cleared first) with the self pairs of `mesh` (unless `self_pairs` is false)
  /// and, if `collider` is given, the pairs between `mesh` and `collider` (none within the
  /// collider), that may come closer than `radius` (position units, finite, >= 0) anywhere
  /// along the motions. Fails on a negative or non-finite radius, position vectors of the wrong
  /// size or a non-finite coordinate.
  Result<void> find(const MeshMotion& mesh, double radius, ContactCandidates& out,
                    const MeshMotion* collider = nullptr, bool self_pairs = true);

 private:
  std::vector<broad_phase_detail::Box> boxes_;
  // The collider's vertices', edges' and triangles' boxes in hierarchies, refitted at each
  // query; rebuilt when their count changes or refitting leaves them twice as loose as built.
  std::array<BoxTree, 3> collider_trees_;
  std::array<double, 3> built_area_{};
  std::vector<broad_phase_detail::CellSpan> spans_;
  std::vector<broad_phase_detail::CellEntry> entries_, scratch_;
  std::vector<VertexTriangleCandidate> vertex_triangle_scratch_;
  std::vector<EdgeEdgeCandidate> edge_edge_scratch_;
};

}  // namespace animkit
