#include "animkit/collision/broad_phase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <utility>

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
  if (const std::vector<double>* radius = motion.vertex_radius) {
    if (radius->size() != static_cast<std::size_t>(motion.mesh.vertex_count)) {
      return Error{std::string(name) + " vertex radii number " + std::to_string(radius->size()) +
                   ", expected one per vertex (" + std::to_string(motion.mesh.vertex_count) + ")"};
    }
    for (std::size_t v = 0; v < radius->size(); ++v) {
      if (!(std::isfinite((*radius)[v]) && (*radius)[v] >= 0.0))
        return Error{std::string(name) + " vertex " + std::to_string(v) +
                     " has a radius that is not finite and >= 0"};
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

using broad_phase_detail::Box;
using broad_phase_detail::CellEntry;
using broad_phase_detail::CellSpan;

// Global primitive indices: [offsets[k], offsets[k + 1]) are the primitives of kind k.
struct PrimitiveRanges {
  std::array<int, 6> counts{};
  std::array<int, 7> offsets{};

  PrimitiveRanges(const CollisionMesh& mesh, const CollisionMesh* collider) {
    counts = {mesh.vertex_count, static_cast<int>(mesh.edges.size()),
              static_cast<int>(mesh.triangles.size())};
    if (collider != nullptr) {
      counts[3] = collider->vertex_count;
      counts[4] = static_cast<int>(collider->edges.size());
      counts[5] = static_cast<int>(collider->triangles.size());
    }
    for (int k = 0; k < 6; ++k) offsets[k + 1] = offsets[k] + counts[k];
  }
  int total() const { return offsets[6]; }
  int kind_of(int primitive) const {
    int k = 0;
    while (primitive >= offsets[k + 1]) ++k;
    return k;
  }
};

// Stage 1: swept boxes, inflated by radius / 2 each, so boxes overlap when the primitives come
// closer than the radius (per axis, so certainly in distance).
void build_boxes(const MeshMotion& mesh, const MeshMotion* collider, double radius,
                 const PrimitiveRanges& ranges, std::vector<Box>& boxes) {
  boxes.resize(ranges.total());
  const auto box_of = [radius](const MeshMotion& m, const int* vertices, int n, Box& box) {
    box.lo = box.hi = m.start.segment<3>(3 * vertices[0]);
    double reach = 0.0;
    for (int i = 0; i < n; ++i) {
      for (const Eigen::VectorXd* x : {&m.start, &m.end}) {
        const Vec3 p = x->segment<3>(3 * vertices[i]);
        box.lo = box.lo.cwiseMin(p);
        box.hi = box.hi.cwiseMax(p);
      }
      if (m.vertex_radius != nullptr)
        reach = std::max(reach, (*m.vertex_radius)[static_cast<std::size_t>(vertices[i])]);
    }
    box.lo.array() -= 0.5 * radius + reach;
    box.hi.array() += 0.5 * radius + reach;
  };
  for (int side = 0; side < 2; ++side) {
    const MeshMotion* m = side == 0 ? &mesh : collider;
    if (m == nullptr) continue;
    const int base = 3 * side;
    for (int v = 0; v < ranges.counts[base]; ++v) {
      box_of(*m, &v, 1, boxes[ranges.offsets[base] + v]);
    }
    for (int e = 0; e < ranges.counts[base + 1]; ++e) {
      box_of(*m, m->mesh.edges[e].data(), 2, boxes[ranges.offsets[base + 1] + e]);
    }
    for (int t = 0; t < ranges.counts[base + 2]; ++t) {
      box_of(*m, m->mesh.triangles[t].data(), 3, boxes[ranges.offsets[base + 2] + t]);
    }
  }
}

// Stage 2: the uniform grid, over the mesh's boxes alone (the collider's pairs come from its
// box trees, stage 5). Origin at their lower corner; cell size their mean size, doubled while a
// cell key would need more than 20 bits per axis or the boxes would fill more than 16 cells each
// on average (which bounds the work by the number of boxes).
struct HashGrid {
  Vec3 origin = Vec3::Zero();
  double cell = 1.0;
  std::array<std::int64_t, 3> dims{1, 1, 1};

  std::int64_t coordinate(double x, int axis) const {
    const auto c = static_cast<std::int64_t>(std::floor((x - origin[axis]) / cell));
    return std::clamp<std::int64_t>(c, 0, dims[axis] - 1);
  }
  std::uint64_t key(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return static_cast<std::uint64_t>((i * dims[1] + j) * dims[2] + k);
  }
  std::uint64_t key(const Vec3& p) const {
    return key(coordinate(p.x(), 0), coordinate(p.y(), 1), coordinate(p.z(), 2));
  }
  std::uint64_t cells_of(const Box& box) const {
    std::uint64_t n = 1;
    for (int a = 0; a < 3; ++a) {
      n *= static_cast<std::uint64_t>(coordinate(box.hi[a], a) - coordinate(box.lo[a], a) + 1);
    }
    return n;
  }

  // Over boxes[0, count), count >= 1.
  static HashGrid fit(const std::vector<Box>& boxes, int count) {
    HashGrid grid;
    grid.origin = boxes[0].lo;
    Vec3 top = boxes[0].hi;
    double mean_size = 0.0;
    for (int b = 0; b < count; ++b) {
      grid.origin = grid.origin.cwiseMin(boxes[b].lo);
      top = top.cwiseMax(boxes[b].hi);
      mean_size += (boxes[b].hi - boxes[b].lo).maxCoeff();
    }
    mean_size /= static_cast<double>(count);
    const double extent = (top - grid.origin).maxCoeff();
    grid.cell = mean_size > 0.0 ? mean_size : (extent > 0.0 ? extent : 1.0);
    constexpr double kMaxCellsPerAxis = 1 << 20;  // the 3D key stays below 2^61
    while (extent / grid.cell > kMaxCellsPerAxis) grid.cell *= 2.0;
    const std::uint64_t budget = 16 * static_cast<std::uint64_t>(count) + 64;
    while (true) {
      for (int a = 0; a < 3; ++a) {
        grid.dims[a] =
            static_cast<std::int64_t>(std::floor((top[a] - grid.origin[a]) / grid.cell)) + 1;
      }
      std::uint64_t total = 0;
      for (int b = 0; b < count && total <= budget; ++b) total += grid.cells_of(boxes[b]);
      if (total <= budget) return grid;
      grid.cell *= 2.0;
    }
  }
};

// One pass of a least significant digit radix sort (stable): the items by digit(item), in
// [0, 2^kDigitBits).
constexpr int kDigitBits = 11;

template <class T, class Digit>
void sort_by_digit(std::vector<T>& items, std::vector<T>& scratch, Digit digit) {
  std::array<std::size_t, (1 << kDigitBits) + 1> start{};
  for (const T& item : items) ++start[digit(item) + 1];
  for (std::size_t d = 0; d + 1 < start.size(); ++d) start[d + 1] += start[d];
  scratch.resize(items.size());
  for (const T& item : items) scratch[start[digit(item)]++] = item;
  items.swap(scratch);
}

// Sorts entries by cell, stably: least significant digit radix sort (Knuth, TAOCP vol. 3,
// 5.2.5) over the key's digits below the grid's cell count. The entries arrive in primitive
// order, so the result is the (cell, primitive) order of a comparison sort, in time linear in
// the entries instead of n log n (this sort was the broad phase's main cost).
void sort_by_cell(std::uint64_t cell_count, std::vector<CellEntry>& entries,
                  std::vector<CellEntry>& scratch) {
  constexpr std::uint64_t kMask = (1u << kDigitBits) - 1;
  for (int shift = 0; shift < 64 && ((cell_count - 1) >> shift) != 0; shift += kDigitBits) {
    sort_by_digit(entries, scratch, [&](const CellEntry& e) { return (e.cell >> shift) & kMask; });
  }
}

// Stage 3: every mesh box (boxes[0, count)) in every cell it overlaps, sorted by (cell,
// primitive), and each box's span of cells.
void fill_cells(const HashGrid& grid, const std::vector<Box>& boxes, int count,
                std::vector<CellSpan>& spans, std::vector<CellEntry>& entries,
                std::vector<CellEntry>& scratch) {
  entries.clear();
  spans.resize(static_cast<std::size_t>(count));
  for (int p = 0; p < count; ++p) {
    const Box& box = boxes[p];
    CellSpan& span = spans[p];
    for (int a = 0; a < 3; ++a) {
      span.lo[a] = static_cast<int>(grid.coordinate(box.lo[a], a));
      span.hi[a] = static_cast<int>(grid.coordinate(box.hi[a], a));
    }
    for (int i = span.lo[0]; i <= span.hi[0]; ++i) {
      for (int j = span.lo[1]; j <= span.hi[1]; ++j) {
        for (int k = span.lo[2]; k <= span.hi[2]; ++k) entries.push_back({grid.key(i, j, k), p});
      }
    }
  }
  const auto cells = static_cast<std::uint64_t>(grid.dims[0] * grid.dims[1] * grid.dims[2]);
  sort_by_cell(cells, entries, scratch);
}

// Stage 4: the mesh's self pairs of primitives sharing a cell, with overlapping boxes,
// reported from the cell of their intersection's lower corner only (that corner lies in both
// boxes, so exactly one shared cell qualifies and no pair comes out twice). A cell's entries are
// sorted by primitive, so each kind is one run of them: only the runs of wanted kinds meet (a
// vertex with a triangle, two edges), never two vertices or two triangles, which a loop over
// every two entries of the cell spends most of its time rejecting.
class PairCollector {
 public:
  PairCollector(const HashGrid& grid, const std::vector<Box>& boxes,
                const std::vector<CellSpan>& spans, const PrimitiveRanges& ranges,
                const CollisionMesh& self, ContactCandidates& out)
      : grid_(grid), boxes_(boxes), spans_(spans), ranges_(ranges), self_(self), out_(out) {}

  void collect(const std::vector<CellEntry>& entries) {
    for (std::size_t begin = 0; begin < entries.size();) {
      std::size_t end = begin;
      while (end < entries.size() && entries[end].cell == entries[begin].cell) ++end;
      collect_cell(entries.data() + begin, entries.data() + end);
      begin = end;
    }
  }

 private:
  using Run = std::pair<const CellEntry*, const CellEntry*>;

  void collect_cell(const CellEntry* first, const CellEntry* last) {
    // The cell's coordinates, from its key (i * ny + j) * nz + k.
    const auto key = static_cast<std::int64_t>(first->cell);
    cell_ = {static_cast<int>(key / (grid_.dims[1] * grid_.dims[2])),
             static_cast<int>(key / grid_.dims[2] % grid_.dims[1]),
             static_cast<int>(key % grid_.dims[2])};
    std::array<Run, 3> runs;
    const CellEntry* at = first;
    for (int kind = 0; kind < 3; ++kind) {
      const CellEntry* run_end = at;
      while (run_end != last && run_end->primitive < ranges_.offsets[kind + 1]) ++run_end;
      runs[kind] = {at, run_end};
      at = run_end;
    }
    each_pair(runs[kVertex], runs[kTriangle], [&](int v, int t) {
      if (!in_triangle(v, self_.triangles[t])) out_.vertex_triangle.push_back({v, t});
    });
    for (const CellEntry* a = runs[kEdge].first; a != runs[kEdge].second; ++a) {
      each_pair({a, a + 1}, {a + 1, runs[kEdge].second}, [&](int e, int f) {
        if (!shares_vertex(self_.edges[e], self_.edges[f])) out_.edge_edge.push_back({e, f});
      });
    }
  }

  // Every entry of `as` with every entry of `bs` whose boxes overlap, reported from this cell:
  // report(index of a within its kind, index of b within its kind).
  template <class Report>
  void each_pair(Run as, Run bs, Report&& report) const {
    if (as.first == as.second || bs.first == bs.second) return;
    const int base_a = ranges_.offsets[ranges_.kind_of(as.first->primitive)];
    const int base_b = ranges_.offsets[ranges_.kind_of(bs.first->primitive)];
    for (const CellEntry* a = as.first; a != as.second; ++a) {
      const Box& box_a = boxes_[a->primitive];
      const CellSpan& span_a = spans_[a->primitive];
      for (const CellEntry* b = bs.first; b != bs.second; ++b) {
        const Box& box_b = boxes_[b->primitive];
        if (!boxes_overlap(box_a, box_b)) continue;
        // The cell of the intersection's lower corner: the grid's coordinate is monotone, so
        // it is the larger of the two boxes' lower cells along each axis.
        const CellSpan& span_b = spans_[b->primitive];
        bool here = true;
        for (int axis = 0; axis < 3; ++axis)
          here = here && std::max(span_a.lo[axis], span_b.lo[axis]) == cell_[axis];
        if (here) report(a->primitive - base_a, b->primitive - base_b);
      }
    }
  }

  const HashGrid& grid_;
  const std::vector<Box>& boxes_;
  const std::vector<CellSpan>& spans_;
  const PrimitiveRanges& ranges_;
  const CollisionMesh& self_;
  ContactCandidates& out_;
  std::array<int, 3> cell_{};  // the cell being collected, (i, j, k)
};

// Sorts candidate pairs (two non-negative indices) lexicographically: radix passes over the
// second index's digits, then the first's (Knuth, TAOCP vol. 3, 5.2.5), each pass linear; the
// lists are long (some 20,000 pairs a query on a draped 41 x 41 sheet) and a comparison sort
// of them took a fifth of the query.
template <class T, class First, class Second>
void sort_pairs(std::vector<T>& pairs, std::vector<T>& scratch, First first, Second second) {
  int first_max = 0, second_max = 0;
  for (const T& p : pairs) {
    first_max = std::max(first_max, first(p));
    second_max = std::max(second_max, second(p));
  }
  constexpr unsigned kMask = (1u << kDigitBits) - 1;
  // Shifts 0, 11 and 22 cover every non-negative int.
  for (int shift = 0; shift < 32 && (shift == 0 || (second_max >> shift) != 0);
       shift += kDigitBits) {
    sort_by_digit(pairs, scratch,
                  [&](const T& p) { return (static_cast<unsigned>(second(p)) >> shift) & kMask; });
  }
  for (int shift = 0; shift < 32 && (shift == 0 || (first_max >> shift) != 0);
       shift += kDigitBits) {
    sort_by_digit(pairs, scratch,
                  [&](const T& p) { return (static_cast<unsigned>(first(p)) >> shift) & kMask; });
  }
}

// Stage 5: the mesh's pairs with the collider, each mesh primitive's box against the tree of the
// collider's boxes of the wanted kind. The leaf test is stage 4's, so the pairs are those of
// testing every two boxes.
void collect_collider_pairs(const std::vector<Box>& all_boxes, const PrimitiveRanges& ranges,
                            std::array<BoxTree, 3>& trees, std::array<double, 3>& built_area,
                            ContactCandidates& out) {
  // trees[k] holds the collider's primitives of kind kColliderVertex + k.
  const auto boxes_of = [&](int kind) { return all_boxes.data() + ranges.offsets[kind]; };
  for (int k = 0; k < 3; ++k) {
    const Box* boxes = boxes_of(kColliderVertex + k);
    const int count = ranges.counts[kColliderVertex + k];
    BoxTree& tree = trees[static_cast<std::size_t>(k)];
    // Twice as loose as when built: colliders moving apart, or a new collider.
    if (tree.size() != count || tree.refit(boxes) > 2.0 * built_area[k]) {
      tree.build(boxes, count);
      built_area[k] = tree.refit(boxes);
    }
  }
  // Each mesh primitive of `kind` against the collider's primitives of `collider_kind`.
  const auto query = [&](int kind, int collider_kind, auto&& report) {
    const BoxTree& tree = trees[static_cast<std::size_t>(collider_kind - kColliderVertex)];
    for (int p = 0; p < ranges.counts[kind]; ++p) {
      tree.overlapping(boxes_of(kind)[p], boxes_of(collider_kind), [&](int c) { report(p, c); });
    }
  };
  query(kVertex, kColliderTriangle, [&](int v, int t) {
    out.vertex_collider_triangle.push_back({v, t});
  });
  query(kTriangle, kColliderVertex, [&](int t, int v) {
    out.collider_vertex_triangle.push_back({v, t});
  });
  query(kEdge, kColliderEdge, [&](int e, int f) { out.edge_collider_edge.push_back({e, f}); });
}

}  // namespace

Result<void> BroadPhase::find(const MeshMotion& mesh, double radius, ContactCandidates& out,
                              const MeshMotion* collider, bool self_pairs) {
  out.clear();
  if (!(std::isfinite(radius) && radius >= 0.0)) {
    return fail("broad phase radius must be finite and >= 0, got " + format_number(radius));
  }
  if (auto error = check_motion(mesh, "mesh")) return std::unexpected(*error);
  if (collider != nullptr) {
    if (auto error = check_motion(*collider, "collider")) return std::unexpected(*error);
  }
  const PrimitiveRanges ranges(mesh.mesh, collider != nullptr ? &collider->mesh : nullptr);
  build_boxes(mesh, collider, radius, ranges, boxes_);
  const int mesh_boxes = ranges.offsets[3];
  if (self_pairs && mesh_boxes > 0) {
    const HashGrid grid = HashGrid::fit(boxes_, mesh_boxes);
    fill_cells(grid, boxes_, mesh_boxes, spans_, entries_, scratch_);
    PairCollector(grid, boxes_, spans_, ranges, mesh.mesh, out).collect(entries_);
  }
  if (collider != nullptr)
    collect_collider_pairs(boxes_, ranges, collider_trees_, built_area_, out);
  const auto vertex = [](const VertexTriangleCandidate& c) { return c.vertex; };
  const auto triangle = [](const VertexTriangleCandidate& c) { return c.triangle; };
  const auto edge_a = [](const EdgeEdgeCandidate& c) { return c.edge_a; };
  const auto edge_b = [](const EdgeEdgeCandidate& c) { return c.edge_b; };
  sort_pairs(out.vertex_triangle, vertex_triangle_scratch_, vertex, triangle);
  sort_pairs(out.edge_edge, edge_edge_scratch_, edge_a, edge_b);
  sort_pairs(out.vertex_collider_triangle, vertex_triangle_scratch_, vertex, triangle);
  sort_pairs(out.collider_vertex_triangle, vertex_triangle_scratch_, vertex, triangle);
  sort_pairs(out.edge_collider_edge, edge_edge_scratch_, edge_a, edge_b);
  return {};
}

}  // namespace animkit
