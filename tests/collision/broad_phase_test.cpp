#include "animkit/collision/broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>

#include "animkit/collision/distance_type.h"

namespace animkit {
namespace {

// An n x n grid of vertices with spacing h in the xz plane, two triangles per quad.
struct Grid {
  CollisionMesh mesh;
  Eigen::VectorXd positions;
};

Grid make_grid(int n, double h) {
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const int v = i * n + j;
      triangles.push_back({v, v + 1, v + n});
      triangles.push_back({v + 1, v + n + 1, v + n});
    }
  }
  Grid grid{build_collision_mesh(n * n, triangles).value(), Eigen::VectorXd(3 * n * n)};
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) grid.positions.segment<3>(3 * (i * n + j)) = Vec3(j * h, 0, i * h);
  }
  return grid;
}

// The grid folded in half onto itself: the half with x > middle mirrored over, `gap` above.
Eigen::VectorXd folded(const Grid& grid, double middle, double gap) {
  Eigen::VectorXd x = grid.positions;
  for (int v = 0; v < grid.mesh.vertex_count; ++v) {
    if (x[3 * v] > middle) {
      x[3 * v] = 2 * middle - x[3 * v];
      x[3 * v + 1] = gap;
    }
  }
  return x;
}

Eigen::VectorXd jittered(const Eigen::VectorXd& x, double amount, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-amount, amount);
  Eigen::VectorXd out = x;
  for (Eigen::Index i = 0; i < out.size(); ++i) out[i] += u(rng);
  return out;
}

Vec3 at(const Eigen::VectorXd& x, int v) {
  return x.segment<3>(3 * v);
}

template <class Pair>
bool contains(const std::vector<Pair>& list, const Pair& pair) {
  return std::binary_search(list.begin(), list.end(), pair);
}

// Every pair closer than `radius` in configuration (x, y) of meshes (a, b) — b == a for self
// pairs, skipping those that share a vertex — must be among the candidates.
void expect_superset(const CollisionMesh& a, const Eigen::VectorXd& x, const CollisionMesh& b,
                     const Eigen::VectorXd& y, bool self,
                     const std::vector<VertexTriangleCandidate>& vertex_triangle,
                     const std::vector<EdgeEdgeCandidate>& edge_edge, double radius,
                     int& close_pairs) {
  const double r2 = radius * radius;
  for (int v = 0; v < a.vertex_count; ++v) {
    for (int t = 0; t < static_cast<int>(b.triangles.size()); ++t) {
      const auto& tri = b.triangles[t];
      if (self && (v == tri[0] || v == tri[1] || v == tri[2])) continue;
      if (point_triangle_distance_squared(at(x, v), at(y, tri[0]), at(y, tri[1]), at(y, tri[2])) <
          r2) {
        ++close_pairs;
        EXPECT_TRUE(contains(vertex_triangle, {v, t})) << "vertex " << v << " triangle " << t;
      }
    }
  }
  for (int e = 0; e < static_cast<int>(a.edges.size()); ++e) {
    for (int f = self ? e + 1 : 0; f < static_cast<int>(b.edges.size()); ++f) {
      const auto &p = a.edges[e], &q = b.edges[f];
      if (self && (p[0] == q[0] || p[0] == q[1] || p[1] == q[0] || p[1] == q[1])) continue;
      if (edge_edge_distance_squared(at(x, p[0]), at(x, p[1]), at(y, q[0]), at(y, q[1])) < r2) {
        ++close_pairs;
        EXPECT_TRUE(contains(edge_edge, {e, f})) << "edges " << e << " " << f;
      }
    }
  }
}

// Lists strictly sorted (so unique), no self pair sharing a vertex.
void expect_well_formed(const CollisionMesh& mesh, const ContactCandidates& c) {
  EXPECT_TRUE(std::adjacent_find(c.vertex_triangle.begin(), c.vertex_triangle.end(),
                                 std::greater_equal<>()) == c.vertex_triangle.end());
  EXPECT_TRUE(std::adjacent_find(c.edge_edge.begin(), c.edge_edge.end(), std::greater_equal<>()) ==
              c.edge_edge.end());
  for (const auto& [v, t] : c.vertex_triangle) {
    const auto& tri = mesh.triangles[t];
    EXPECT_TRUE(v != tri[0] && v != tri[1] && v != tri[2]);
  }
  for (const auto& [e, f] : c.edge_edge) {
    const auto &p = mesh.edges[e], &q = mesh.edges[f];
    EXPECT_LT(e, f);
    EXPECT_TRUE(p[0] != q[0] && p[0] != q[1] && p[1] != q[0] && p[1] != q[1]);
  }
}

TEST(BroadPhase, SelfPairsAreASupersetOfBruteForceAtAConfiguration) {
  std::mt19937 rng(51);
  const Grid grid = make_grid(16, 0.1);
  BroadPhase broad_phase;
  ContactCandidates candidates;
  int close_pairs = 0;
  // A crumpled cloth (random jitter of half the spacing) and the cloth folded onto itself.
  const std::array<Eigen::VectorXd, 3> configurations = {
      jittered(grid.positions, 0.05, rng), jittered(grid.positions, 0.12, rng),
      jittered(folded(grid, 0.75, 0.03), 0.01, rng)};
  for (const Eigen::VectorXd& x : configurations) {
    for (double radius : {0.0, 0.02, 0.06}) {
      ASSERT_TRUE(broad_phase.find({grid.mesh, x, x}, radius, candidates).has_value());
      expect_well_formed(grid.mesh, candidates);
      expect_superset(grid.mesh, x, grid.mesh, x, true, candidates.vertex_triangle,
                      candidates.edge_edge, radius, close_pairs);
      EXPECT_TRUE(candidates.vertex_collider_triangle.empty());
    }
  }
  EXPECT_GT(close_pairs, 1000);  // the check is not vacuous
}

// Candidates are pairs whose inflated boxes overlap: not all pairs. On the folded cloth with a
// radius below the spacing, far fewer than the n^2 pairs.
TEST(BroadPhase, CandidatesAreFewOnAFoldedCloth) {
  const Grid grid = make_grid(30, 0.1);
  const Eigen::VectorXd x = folded(grid, 1.45, 0.02);
  BroadPhase broad_phase;
  ContactCandidates candidates;
  ASSERT_TRUE(broad_phase.find({grid.mesh, x, x}, 0.03, candidates).has_value());
  const double all_pairs = double(grid.mesh.vertex_count) * double(grid.mesh.triangles.size());
  EXPECT_GT(candidates.vertex_triangle.size(), 500u);  // the two layers see each other
  EXPECT_LT(double(candidates.vertex_triangle.size()), 0.02 * all_pairs);
}

TEST(BroadPhase, MotionPairsContainEveryConfigurationAlongTheMotion) {
  std::mt19937 rng(52);
  const Grid grid = make_grid(12, 0.1);
  const Eigen::VectorXd start = jittered(folded(grid, 0.55, 0.05), 0.02, rng);
  const Eigen::VectorXd end = jittered(start, 0.08, rng);
  BroadPhase broad_phase;
  ContactCandidates candidates;
  const double radius = 0.02;
  ASSERT_TRUE(broad_phase.find({grid.mesh, start, end}, radius, candidates).has_value());
  expect_well_formed(grid.mesh, candidates);
  int close_pairs = 0;
  for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
    const Eigen::VectorXd x = start + t * (end - start);
    expect_superset(grid.mesh, x, grid.mesh, x, true, candidates.vertex_triangle,
                    candidates.edge_edge, radius, close_pairs);
  }
  EXPECT_GT(close_pairs, 100);
}

TEST(BroadPhase, ColliderPairsAreASupersetOfBruteForce) {
  std::mt19937 rng(53);
  const Grid cloth = make_grid(12, 0.1);
  const Grid floor = make_grid(5, 0.3);  // a coarse plane under the cloth
  Eigen::VectorXd floor_start = floor.positions, floor_end = floor.positions;
  for (int v = 0; v < floor.mesh.vertex_count; ++v) {
    floor_start[3 * v + 1] = -0.03;
    floor_end[3 * v + 1] = 0.02;  // rising through the cloth's rest height
  }
  const Eigen::VectorXd start = jittered(cloth.positions, 0.02, rng);
  const Eigen::VectorXd end = jittered(start, 0.02, rng);
  BroadPhase broad_phase;
  ContactCandidates candidates;
  const double radius = 0.01;
  const MeshMotion collider{floor.mesh, floor_start, floor_end};
  ASSERT_TRUE(broad_phase.find({cloth.mesh, start, end}, radius, candidates, &collider));
  int close_pairs = 0;
  for (double t : {0.0, 0.3, 0.6, 1.0}) {
    const Eigen::VectorXd x = start + t * (end - start);
    const Eigen::VectorXd y = floor_start + t * (floor_end - floor_start);
    expect_superset(cloth.mesh, x, floor.mesh, y, false, candidates.vertex_collider_triangle,
                    candidates.edge_collider_edge, radius, close_pairs);
    // The collider's vertices against the cloth's triangles.
    for (int v = 0; v < floor.mesh.vertex_count; ++v) {
      for (int t2 = 0; t2 < static_cast<int>(cloth.mesh.triangles.size()); ++t2) {
        const auto& tri = cloth.mesh.triangles[t2];
        if (point_triangle_distance_squared(at(y, v), at(x, tri[0]), at(x, tri[1]), at(x, tri[2])) <
            radius * radius) {
          ++close_pairs;
          EXPECT_TRUE(contains(candidates.collider_vertex_triangle, {v, t2}));
        }
      }
    }
  }
  EXPECT_GT(close_pairs, 100);
  expect_well_formed(cloth.mesh, candidates);
}

// A primitive's box over a motion, inflated by radius / 2, as the broad phase makes it.
template <std::size_t N>
AlignedBox inflated_box(const std::array<int, N>& vertices, const Eigen::VectorXd& start,
                        const Eigen::VectorXd& end, double radius) {
  AlignedBox box{at(start, vertices[0]), at(start, vertices[0])};
  for (const int v : vertices) {
    for (const Eigen::VectorXd* x : {&start, &end}) {
      box.lo = box.lo.cwiseMin(at(*x, v));
      box.hi = box.hi.cwiseMax(at(*x, v));
    }
  }
  box.lo.array() -= 0.5 * radius;
  box.hi.array() += 0.5 * radius;
  return box;
}

// The collider pairs are exactly those whose boxes overlap: one BroadPhase reused while the
// collider moves (its box trees refitted), for another collider (rebuilt) and back.
TEST(BroadPhase, ColliderPairsAreExactlyTheOverlappingBoxes) {
  std::mt19937 rng(57);
  const Grid cloth = make_grid(12, 0.1);
  const Eigen::VectorXd start = jittered(folded(cloth, 0.55, 0.03), 0.02, rng);
  const Eigen::VectorXd end = jittered(start, 0.02, rng);
  const Grid coarse = make_grid(5, 0.3), fine = make_grid(9, 0.12);
  BroadPhase broad_phase;
  const double radius = 0.01;
  for (const auto& [collider, lift] : {std::pair{&coarse, 0.0}, {&coarse, 0.02}, {&fine, 0.01},
                                       {&coarse, 0.0}}) {
    Eigen::VectorXd y0 = jittered(collider->positions, 0.01, rng), y1 = y0;
    for (int v = 0; v < collider->mesh.vertex_count; ++v) {
      y0[3 * v + 1] += lift - 0.01;
      y1[3 * v + 1] += lift + 0.01;
    }
    const MeshMotion motion{collider->mesh, y0, y1};
    ContactCandidates found;
    ASSERT_TRUE(broad_phase.find({cloth.mesh, start, end}, radius, found, &motion));
    ContactCandidates expected;
    const auto box = [&](const auto& vertices, bool of_collider) {
      return of_collider ? inflated_box(vertices, y0, y1, radius)
                         : inflated_box(vertices, start, end, radius);
    };
    for (int v = 0; v < cloth.mesh.vertex_count; ++v) {
      const AlignedBox vertex_box = box(std::array<int, 1>{v}, false);
      for (int t = 0; t < static_cast<int>(collider->mesh.triangles.size()); ++t) {
        if (boxes_overlap(vertex_box, box(collider->mesh.triangles[t], true)))
          expected.vertex_collider_triangle.push_back({v, t});
      }
    }
    for (int v = 0; v < collider->mesh.vertex_count; ++v) {
      for (int t = 0; t < static_cast<int>(cloth.mesh.triangles.size()); ++t) {
        if (boxes_overlap(box(std::array<int, 1>{v}, true), box(cloth.mesh.triangles[t], false)))
          expected.collider_vertex_triangle.push_back({v, t});
      }
    }
    for (int e = 0; e < static_cast<int>(cloth.mesh.edges.size()); ++e) {
      for (int f = 0; f < static_cast<int>(collider->mesh.edges.size()); ++f) {
        if (boxes_overlap(box(cloth.mesh.edges[e], false), box(collider->mesh.edges[f], true)))
          expected.edge_collider_edge.push_back({e, f});
      }
    }
    std::sort(expected.collider_vertex_triangle.begin(), expected.collider_vertex_triangle.end());
    EXPECT_GT(expected.vertex_collider_triangle.size(), 50u);
    EXPECT_EQ(found.vertex_collider_triangle, expected.vertex_collider_triangle);
    EXPECT_EQ(found.collider_vertex_triangle, expected.collider_vertex_triangle);
    EXPECT_EQ(found.edge_collider_edge, expected.edge_collider_edge);
  }
}

// Without self pairs (a cloth without self-contact) the cloth-collider lists are the same and
// the self lists empty.
TEST(BroadPhase, WithoutSelfPairsOnlyColliderPairsAreFound) {
  std::mt19937 rng(55);
  const Grid cloth = make_grid(10, 0.1), floor = make_grid(4, 0.3);
  const Eigen::VectorXd x = jittered(folded(cloth, 0.45, 0.02), 0.01, rng);
  const Eigen::VectorXd y = jittered(floor.positions, 0.01, rng);
  const MeshMotion collider{floor.mesh, y, y};
  BroadPhase broad_phase;
  ContactCandidates all, colliders_only;
  ASSERT_TRUE(broad_phase.find({cloth.mesh, x, x}, 0.03, all, &collider));
  ASSERT_TRUE(broad_phase.find({cloth.mesh, x, x}, 0.03, colliders_only, &collider, false));
  EXPECT_GT(all.vertex_triangle.size(), 0u);
  EXPECT_GT(all.vertex_collider_triangle.size(), 0u);
  EXPECT_TRUE(colliders_only.vertex_triangle.empty());
  EXPECT_TRUE(colliders_only.edge_edge.empty());
  EXPECT_EQ(colliders_only.vertex_collider_triangle, all.vertex_collider_triangle);
  EXPECT_EQ(colliders_only.collider_vertex_triangle, all.collider_vertex_triangle);
  EXPECT_EQ(colliders_only.edge_collider_edge, all.edge_collider_edge);
}

TEST(BroadPhase, DeterministicAndReusable) {
  std::mt19937 rng(54);
  const Grid big = make_grid(14, 0.1), small = make_grid(4, 0.1);
  const Eigen::VectorXd x = jittered(big.positions, 0.08, rng);
  const Eigen::VectorXd y = jittered(small.positions, 0.08, rng);
  BroadPhase reused, fresh;
  ContactCandidates first, second, other;
  ASSERT_TRUE(reused.find({big.mesh, x, x}, 0.05, first));
  ASSERT_TRUE(reused.find({small.mesh, y, y}, 0.05, other));  // a smaller scene in between
  ASSERT_TRUE(reused.find({big.mesh, x, x}, 0.05, second));
  EXPECT_EQ(first.vertex_triangle, second.vertex_triangle);
  EXPECT_EQ(first.edge_edge, second.edge_edge);
  ASSERT_TRUE(fresh.find({big.mesh, x, x}, 0.05, second));
  EXPECT_EQ(first.vertex_triangle, second.vertex_triangle);
  EXPECT_EQ(first.edge_edge, second.edge_edge);
  EXPECT_GT(first.size(), 0u);
}

// A folded 30 x 30 sheet (some 5,000 primitives) moving over a floor: every close
// pair of a brute-force search is among the candidates, each list sorted and without
// duplicates, at the start and at the end of the motion.
TEST(BroadPhase, ALargeFoldedSheetOverAFloorFindsEveryClosePair) {
  std::mt19937 rng(56);
  const Grid cloth = make_grid(30, 0.033), floor = make_grid(9, 0.125);
  const Eigen::VectorXd start = jittered(folded(cloth, 0.48, 0.01), 0.004, rng);
  const Eigen::VectorXd end = jittered(start, 0.002, rng);
  Eigen::VectorXd y = floor.positions;
  for (int v = 0; v < floor.mesh.vertex_count; ++v) y[3 * v + 1] = -0.004;
  const MeshMotion collider{floor.mesh, y, y};
  BroadPhase broad_phase;
  ContactCandidates found;
  ASSERT_TRUE(broad_phase.find({cloth.mesh, start, end}, 0.006, found, &collider));
  expect_well_formed(cloth.mesh, found);
  EXPECT_GT(found.edge_collider_edge.size(), 1000u);
  int close_pairs = 0;
  for (const Eigen::VectorXd* x : {&start, &end}) {
    expect_superset(cloth.mesh, *x, cloth.mesh, *x, true, found.vertex_triangle,
                    found.edge_edge, 0.006, close_pairs);
    expect_superset(cloth.mesh, *x, floor.mesh, y, false, found.vertex_collider_triangle,
                    found.edge_collider_edge, 0.006, close_pairs);
  }
  EXPECT_GT(close_pairs, 4000);
}

TEST(BroadPhase, RejectsBadInput) {
  const Grid grid = make_grid(3, 0.1);
  BroadPhase broad_phase;
  ContactCandidates out;
  EXPECT_EQ(
      broad_phase.find({grid.mesh, grid.positions, grid.positions}, -1.0, out).error().message,
      "broad phase radius must be finite and >= 0, got -1");
  const Eigen::VectorXd short_positions = grid.positions.head(6);
  EXPECT_EQ(
      broad_phase.find({grid.mesh, grid.positions, short_positions}, 0.1, out).error().message,
      "mesh positions have 6 entries, expected 27 (3 per vertex)");
  Eigen::VectorXd bad = grid.positions;
  bad[13] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(broad_phase.find({grid.mesh, bad, grid.positions}, 0.1, out).error().message,
            "mesh vertex 4 has a non-finite coordinate");
  const std::vector<double> two_radii = {0.1, 0.1};
  EXPECT_EQ(broad_phase.find({grid.mesh, grid.positions, grid.positions, &two_radii}, 0.1, out)
                .error()
                .message,
            "mesh vertex radii number 2, expected one per vertex (9)");
  std::vector<double> radii(9, 0.1);
  radii[3] = -0.1;
  EXPECT_EQ(broad_phase.find({grid.mesh, grid.positions, grid.positions, &radii}, 0.1, out)
                .error()
                .message,
            "mesh vertex 3 has a radius that is not finite and >= 0");
  const std::vector<std::array<int, 3>> out_of_range = {{0, 1, 2}, {1, 2, 9}};
  EXPECT_EQ(build_collision_mesh(4, out_of_range).error().message,
            "triangle 1 has vertex 9 outside [0, 4)");
  const std::vector<std::array<int, 3>> repeated = {{0, 1, 1}};
  EXPECT_EQ(build_collision_mesh(4, repeated).error().message, "triangle 0 repeats vertex 1");
  const std::vector<std::array<int, 3>> two = {{0, 1, 2}, {2, 1, 3}};
  const auto edges = build_collision_mesh(4, two).value().edges;
  EXPECT_EQ(edges, (std::vector<std::array<int, 2>>{{0, 1}, {0, 2}, {1, 2}, {1, 3}, {2, 3}}));
}

}  // namespace
}  // namespace animkit
