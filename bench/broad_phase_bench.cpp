// The broad phase (collision/broad_phase.h) on what a cloth draped over a ball asks of it: a
// cotton sheet of 41 x 41 or 101 x 101 particles lying over a sphere of radius 0.25 m (1,280
// triangles) and the ground around it, like drape-sphere at rest, its own self pairs and its
// pairs with the ball, along a small step (every particle moved by up to 1 mm, as Newton's
// iterates do at rest). Counter: the candidates found. One thread (the broad phase's own).
// Beside it, the straightforward way on the 41 x 41 sheet: every wanted pair of primitives (a
// vertex and a triangle, two edges, each of the sheet with each other and with the ball's)
// whose swept, inflated boxes overlap, by testing them all.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "animkit/collision/broad_phase.h"
#include "animkit/collision/collider_surface.h"
#include "animkit/collision/collision_mesh.h"

namespace {

constexpr double kRadius = 0.25;     // the ball's, centred at (0, kRadius, 0)
constexpr double kThickness = 2e-3;  // the contact distance

struct DrapeGeometry {
  animkit::CollisionMesh cloth, ball;
  Eigen::VectorXd cloth_start, cloth_end, ball_positions;
};

// The sheet over the ball: each particle of the 1 m grid at the height of the ball's top surface
// beneath it, or just above the ground beyond, a contact distance above either; triangles split
// along alternating diagonals as the grid cloth's are.
DrapeGeometry drape_geometry(int particles_per_side) {
  DrapeGeometry g;
  const int n = particles_per_side;
  std::vector<std::array<int, 3>> triangles;
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + 1, c = a + n, d = c + 1;
      if ((i + j) % 2 == 0) {
        triangles.push_back({a, b, d});
        triangles.push_back({a, d, c});
      } else {
        triangles.push_back({a, b, c});
        triangles.push_back({b, d, c});
      }
    }
  }
  g.cloth = *animkit::build_collision_mesh(n * n, triangles);
  g.cloth_start.resize(3 * n * n);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> step(-1e-3, 1e-3);
  g.cloth_end.resize(g.cloth_start.size());
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double x = -0.5 + static_cast<double>(i) / (n - 1);
      const double z = -0.5 + static_cast<double>(j) / (n - 1);
      const double r2 = x * x + z * z;
      const double height = r2 < kRadius * kRadius ? kRadius + std::sqrt(kRadius * kRadius - r2)
                                                   : 0.0;
      const int p = i * n + j;
      g.cloth_start.segment<3>(3 * p) = animkit::Vec3(x, height + 1.5 * kThickness, z);
      for (int a = 0; a < 3; ++a) g.cloth_end[3 * p + a] = g.cloth_start[3 * p + a] + step(random);
    }
  }
  const animkit::TriangleMesh surface =
      animkit::collider_surface(animkit::SphereShape{kRadius}, 3);
  g.ball = *animkit::build_collision_mesh(static_cast<int>(surface.vertices.size()),
                                          surface.triangles);
  g.ball_positions.resize(3 * static_cast<Eigen::Index>(surface.vertices.size()));
  for (std::size_t v = 0; v < surface.vertices.size(); ++v) {
    g.ball_positions.segment<3>(3 * static_cast<Eigen::Index>(v)) =
        surface.vertices[v] + animkit::Vec3(0.0, kRadius, 0.0);
  }
  return g;
}

void broad_phase_drape(benchmark::State& state) {
  const DrapeGeometry g = drape_geometry(static_cast<int>(state.range(0)));
  const animkit::MeshMotion cloth{g.cloth, g.cloth_start, g.cloth_end};
  const animkit::MeshMotion ball{g.ball, g.ball_positions, g.ball_positions};
  animkit::BroadPhase broad_phase;
  animkit::ContactCandidates candidates;
  for (auto _ : state) {
    if (!broad_phase.find(cloth, kThickness, candidates, &ball, true)) {
      state.SkipWithError("the broad phase failed");
      break;
    }
    benchmark::DoNotOptimize(candidates.edge_edge.data());
  }
  state.counters["candidates"] = static_cast<double>(candidates.size());
}

struct Box {
  Eigen::Vector3d lo, hi;
};

// Each primitive's box over both configurations, inflated by the contact distance / 2 (as the
// broad phase makes them).
template <std::size_t N>
std::vector<Box> boxes_of(const std::vector<std::array<int, N>>& primitives,
                          const Eigen::VectorXd& start, const Eigen::VectorXd& end) {
  std::vector<Box> boxes;
  for (const auto& primitive : primitives) {
    Box box{start.segment<3>(3 * primitive[0]), start.segment<3>(3 * primitive[0])};
    for (const int v : primitive) {
      for (const Eigen::VectorXd* x : {&start, &end}) {
        box.lo = box.lo.cwiseMin(x->segment<3>(3 * v));
        box.hi = box.hi.cwiseMax(x->segment<3>(3 * v));
      }
    }
    box.lo.array() -= 0.5 * kThickness;
    box.hi.array() += 0.5 * kThickness;
    boxes.push_back(box);
  }
  return boxes;
}

std::vector<std::array<int, 1>> vertices(int count) {
  std::vector<std::array<int, 1>> v(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) v[static_cast<std::size_t>(i)] = {i};
  return v;
}

// Pairs of `as` and `bs` whose boxes overlap (with `self`, each unordered pair once).
long overlapping(const std::vector<Box>& as, const std::vector<Box>& bs, bool self) {
  long count = 0;
  for (std::size_t a = 0; a < as.size(); ++a) {
    for (std::size_t b = self ? a + 1 : 0; b < bs.size(); ++b) {
      const bool apart = (as[a].lo.array() > bs[b].hi.array()).any() ||
                         (bs[b].lo.array() > as[a].hi.array()).any();
      count += apart ? 0 : 1;
    }
  }
  return count;
}

void broad_phase_drape_all_pairs(benchmark::State& state) {
  const DrapeGeometry g = drape_geometry(41);
  long candidates = 0;
  for (auto _ : state) {
    const auto cloth_vertices = boxes_of(vertices(g.cloth.vertex_count), g.cloth_start,
                                         g.cloth_end);
    const auto cloth_edges = boxes_of(g.cloth.edges, g.cloth_start, g.cloth_end);
    const auto cloth_triangles = boxes_of(g.cloth.triangles, g.cloth_start, g.cloth_end);
    const auto ball_vertices = boxes_of(vertices(g.ball.vertex_count), g.ball_positions,
                                        g.ball_positions);
    const auto ball_edges = boxes_of(g.ball.edges, g.ball_positions, g.ball_positions);
    const auto ball_triangles = boxes_of(g.ball.triangles, g.ball_positions, g.ball_positions);
    candidates = overlapping(cloth_vertices, cloth_triangles, false) +
                 overlapping(cloth_edges, cloth_edges, true) +
                 overlapping(cloth_vertices, ball_triangles, false) +
                 overlapping(ball_vertices, cloth_triangles, false) +
                 overlapping(cloth_edges, ball_edges, false);
    benchmark::DoNotOptimize(candidates);
  }
  // Counts pairs sharing a vertex too, which the broad phase leaves out.
  state.counters["candidates"] = static_cast<double>(candidates);
}

BENCHMARK(broad_phase_drape_all_pairs)->Unit(benchmark::kMillisecond);

BENCHMARK(broad_phase_drape)->ArgName("side")->Arg(41)->Arg(101)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
