#include "animkit/collision/distance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>

#include "animkit/collision/distance_type.h"
#include "stencil_checks.h"

namespace animkit {
namespace {

using test::expect_derivatives_match;
using test::Points;
using test::RandomPoints;
using test::sin2;

// Central differences with h = 1e-6 on coordinates of order 1 are accurate to about 1e-9
// relative; a wrong term (a sign, a factor 2, a missing block) is off by order 1.
constexpr double kTolerance = 1e-6;

TEST(Distance, PointPointDerivativesMatchFiniteDifferences) {
  RandomPoints random(1);
  for (int trial = 0; trial < 100; ++trial) {
    expect_derivatives_match<2>(
        random.points<2>(),
        [](const Points<2>& x) { return point_point_distance_squared_derivatives(x[0], x[1]); },
        kTolerance);
  }
}

TEST(Distance, PointLineDerivativesMatchFiniteDifferences) {
  RandomPoints random(2);
  for (int trial = 0; trial < 200; ++trial) {
    const Points<3> x = random.points<3>();
    if ((x[2] - x[1]).norm() < 0.2 || point_line_distance_squared(x[0], x[1], x[2]) < 1e-2) {
      continue;  // well-conditioned configurations only
    }
    expect_derivatives_match<3>(
        x,
        [](const Points<3>& y) {
          return point_line_distance_squared_derivatives(y[0], y[1], y[2]);
        },
        kTolerance);
    EXPECT_NEAR(point_line_distance_squared_derivatives(x[0], x[1], x[2]).value,
                point_line_distance_squared(x[0], x[1], x[2]), 1e-14);
  }
}

TEST(Distance, PointPlaneDerivativesMatchFiniteDifferences) {
  RandomPoints random(3);
  for (int trial = 0; trial < 200; ++trial) {
    const Points<4> x = random.points<4>();
    if (sin2(x[2] - x[1], x[3] - x[1]) < 0.05 || (x[2] - x[1]).norm() < 0.2 ||
        (x[3] - x[1]).norm() < 0.2) {
      continue;
    }
    expect_derivatives_match<4>(
        x,
        [](const Points<4>& y) {
          return point_plane_distance_squared_derivatives(y[0], y[1], y[2], y[3]);
        },
        kTolerance);
  }
}

TEST(Distance, LineLineDerivativesMatchFiniteDifferences) {
  RandomPoints random(4);
  for (int trial = 0; trial < 200; ++trial) {
    const Points<4> x = random.points<4>();
    if (sin2(x[1] - x[0], x[3] - x[2]) < 0.05 || (x[1] - x[0]).norm() < 0.2 ||
        (x[3] - x[2]).norm() < 0.2) {
      continue;
    }
    expect_derivatives_match<4>(
        x,
        [](const Points<4>& y) {
          return line_line_distance_squared_derivatives(y[0], y[1], y[2], y[3]);
        },
        kTolerance);
  }
}

TEST(Distance, HandComputedValues) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 2, 0);
  EXPECT_DOUBLE_EQ(point_line_distance_squared(Vec3(5, 3, 4), a, b), 25.0);
  EXPECT_DOUBLE_EQ(point_plane_distance_squared(Vec3(7, -3, 0.5), a, b, c), 0.25);
  EXPECT_DOUBLE_EQ(line_line_distance_squared(a, b, Vec3(9, 1, 3), Vec3(9, 4, 3)), 9.0);
  EXPECT_DOUBLE_EQ(point_triangle_distance_squared(Vec3(3, 0, 1), a, b, c), 2.0);  // vertex b
  EXPECT_DOUBLE_EQ(point_triangle_distance_squared(Vec3(2, 2, 0), a, b, c), 2.0);  // edge bc
  EXPECT_DOUBLE_EQ(point_triangle_distance_squared(Vec3(0.5, 0.5, -3), a, b, c), 9.0);
  EXPECT_EQ(point_triangle_distance_type(Vec3(-1, 1, 0), a, b, c),
            PointTriangleDistanceType::kEdgeCA);
}

// Every classified formula's derivatives, with the type held fixed (the FD stencil stays in one
// smooth piece); every type must come up on random configurations.
TEST(Distance, ClassifiedDerivativesMatchFiniteDifferencesForEveryType) {
  RandomPoints random(5);
  std::array<int, 7> triangle_hits{};
  std::array<int, 9> edge_hits{};
  for (int trial = 0; trial < 3000; ++trial) {
    Points<4> x = random.points<4>();
    x[0] *= 2.0;  // the point often outside the triangle's prism
    if (sin2(x[2] - x[1], x[3] - x[1]) > 0.05 &&
        point_triangle_distance_squared(x[0], x[1], x[2], x[3]) > 1e-2) {
      const auto type = point_triangle_distance_type(x[0], x[1], x[2], x[3]);
      ++triangle_hits[static_cast<int>(type)];
      expect_derivatives_match<4>(
          x,
          [type](const Points<4>& y) {
            return point_triangle_distance_squared_derivatives(y[0], y[1], y[2], y[3], type);
          },
          kTolerance);
    }
    const Points<4> y = random.points<4>();
    if (sin2(y[1] - y[0], y[3] - y[2]) > 0.05 &&
        edge_edge_distance_squared(y[0], y[1], y[2], y[3]) > 1e-2) {
      const auto type = edge_edge_distance_type(y[0], y[1], y[2], y[3]);
      ++edge_hits[static_cast<int>(type)];
      expect_derivatives_match<4>(
          y,
          [type](const Points<4>& z) {
            return edge_edge_distance_squared_derivatives(z[0], z[1], z[2], z[3], type);
          },
          kTolerance);
    }
  }
  for (int hits : triangle_hits) EXPECT_GT(hits, 0);
  for (int hits : edge_hits) EXPECT_GT(hits, 0);
}

// The gradient-only functions give the full derivatives' value and gradient: for every
// classified type, and for each smooth formula. (The same formulas, compiled apart: equal up to
// the rounding of fused multiply-adds.)
template <int V>
void expect_same_gradient(const StencilGradient<V>& alone, const StencilDerivatives<V>& full) {
  const double scale = 1.0 + std::abs(full.value) + full.gradient.norm();
  EXPECT_NEAR(alone.value, full.value, 1e-14 * scale);
  EXPECT_LE((alone.gradient - full.gradient).norm(), 1e-14 * scale);
}

TEST(Distance, GradientsAloneAreTheFullDerivativesGradients) {
  RandomPoints random(8);
  std::array<int, 7> triangle_hits{};
  std::array<int, 9> edge_hits{};
  for (int trial = 0; trial < 3000; ++trial) {
    Points<4> x = random.points<4>();
    x[0] *= 2.0;
    const auto triangle = point_triangle_distance_type(x[0], x[1], x[2], x[3]);
    ++triangle_hits[static_cast<int>(triangle)];
    expect_same_gradient<4>(
        point_triangle_distance_squared_gradient(x[0], x[1], x[2], x[3], triangle),
        point_triangle_distance_squared_derivatives(x[0], x[1], x[2], x[3], triangle));
    const auto edges = edge_edge_distance_type(x[0], x[1], x[2], x[3]);
    ++edge_hits[static_cast<int>(edges)];
    expect_same_gradient<4>(edge_edge_distance_squared_gradient(x[0], x[1], x[2], x[3], edges),
                            edge_edge_distance_squared_derivatives(x[0], x[1], x[2], x[3], edges));
  }
  for (int hits : triangle_hits) EXPECT_GT(hits, 0);
  for (int hits : edge_hits) EXPECT_GT(hits, 0);
  const Points<4> y = random.points<4>();
  expect_same_gradient<2>(point_point_distance_squared_gradient(y[0], y[1]),
                          point_point_distance_squared_derivatives(y[0], y[1]));
  expect_same_gradient<3>(point_line_distance_squared_gradient(y[0], y[1], y[2]),
                          point_line_distance_squared_derivatives(y[0], y[1], y[2]));
  expect_same_gradient<4>(point_plane_distance_squared_gradient(y[0], y[1], y[2], y[3]),
                          point_plane_distance_squared_derivatives(y[0], y[1], y[2], y[3]));
  expect_same_gradient<4>(line_line_distance_squared_gradient(y[0], y[1], y[2], y[3]),
                          line_line_distance_squared_derivatives(y[0], y[1], y[2], y[3]));
}

// Brute force: the minimum over a fine sampling of the primitives. The sampled minimum is an
// upper bound of the true one and within `resolution` of it in distance (not squared).
// `slack` allows the parallel fallback's own error (of order |u| |v| sin(angle) <= 1e-11 here).
void expect_matches_sampled_minimum(double classified, double sampled, double resolution,
                                    double slack = 1e-12) {
  EXPECT_LE(classified, sampled + slack) << std::setprecision(17) << classified - sampled;
  EXPECT_GE(std::sqrt(classified), std::sqrt(sampled) - resolution)
      << "classified " << classified << " sampled " << sampled;
}

double sampled_point_edge(const Vec3& p, const Vec3& a, const Vec3& b, int n) {
  double best = (p - a).squaredNorm();
  for (int i = 1; i <= n; ++i) best = std::min(best, (p - (a + (b - a) * i / n)).squaredNorm());
  return best;
}

double sampled_point_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c, int n) {
  double best = (p - a).squaredNorm();
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; i + j <= n; ++j) {
      const Vec3 q = a + (b - a) * (double(i) / n) + (c - a) * (double(j) / n);
      best = std::min(best, (p - q).squaredNorm());
    }
  }
  return best;
}

// Edge a sampled, each sample against edge b by the (separately checked) point-edge distance.
double sampled_edge_edge(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1, int n) {
  double best = point_edge_distance_squared(a0, b0, b1);
  for (int i = 1; i <= n; ++i) {
    best = std::min(best, point_edge_distance_squared(a0 + (a1 - a0) * i / n, b0, b1));
  }
  return best;
}

TEST(Distance, ClassificationMatchesSampledMinimum) {
  RandomPoints random(6);
  constexpr int kSamples = 300;
  for (int trial = 0; trial < 300; ++trial) {
    const Points<4> x = random.points<4>();
    const Vec3 p = 2.0 * x[0];
    expect_matches_sampled_minimum(point_edge_distance_squared(p, x[1], x[2]),
                                   sampled_point_edge(p, x[1], x[2], 10 * kSamples),
                                   (x[2] - x[1]).norm() / (10 * kSamples));
    expect_matches_sampled_minimum(point_triangle_distance_squared(p, x[1], x[2], x[3]),
                                   sampled_point_triangle(p, x[1], x[2], x[3], kSamples),
                                   ((x[2] - x[1]).norm() + (x[3] - x[1]).norm()) / kSamples);
    expect_matches_sampled_minimum(edge_edge_distance_squared(x[0], x[1], x[2], x[3]),
                                   sampled_edge_edge(x[0], x[1], x[2], x[3], 10 * kSamples),
                                   (x[1] - x[0]).norm() / (10 * kSamples));
  }
}

// Parallel edges (exactly, and at an angle below the tolerance), point in the triangle's plane,
// degenerate triangles and edges: never the formula that divides by |u x v|^2 ~ 0, and still
// the minimum distance.
TEST(Distance, DegenerateConfigurationsMatchSampledMinimum) {
  RandomPoints random(7);
  constexpr int kSamples = 3000;
  for (int trial = 0; trial < 200; ++trial) {
    const Points<4> x = random.points<4>();
    const Vec3 u = x[1] - x[0];
    for (double scale : {0.7, -1.3}) {
      const Vec3 b1 = x[2] + scale * u + (trial % 2 == 0 ? Vec3::Zero() : Vec3(0, 1e-12, 0));
      const auto type = edge_edge_distance_type(x[0], x[1], x[2], b1);
      if (trial % 2 == 0) {
        EXPECT_NE(type, EdgeEdgeDistanceType::kInterior);
      }
      expect_matches_sampled_minimum(edge_edge_distance_squared(x[0], x[1], x[2], b1, type),
                                     sampled_edge_edge(x[0], x[1], x[2], b1, kSamples),
                                     u.norm() / kSamples, 1e-10);
    }
    // Point in the plane of the triangle, and a triangle squashed onto a line.
    const Vec3 in_plane = x[1] + 1.5 * random.uniform(-1, 1) * (x[2] - x[1]) +
                          1.5 * random.uniform(-1, 1) * (x[3] - x[1]);
    expect_matches_sampled_minimum(point_triangle_distance_squared(in_plane, x[1], x[2], x[3]),
                                   sampled_point_triangle(in_plane, x[1], x[2], x[3], 300),
                                   ((x[2] - x[1]).norm() + (x[3] - x[1]).norm()) / 300);
    const Vec3 collinear = x[1] + 0.4 * (x[2] - x[1]);
    const auto type = point_triangle_distance_type(x[0], x[1], x[2], collinear);
    EXPECT_NE(type, PointTriangleDistanceType::kInterior);
    expect_matches_sampled_minimum(point_triangle_distance_squared(x[0], x[1], x[2], collinear),
                                   sampled_point_edge(x[0], x[1], x[2], kSamples),
                                   (x[2] - x[1]).norm() / kSamples);
  }
  // Zero-length edges and a triangle collapsed to a point.
  const Vec3 p(1, 2, 3), q(0, 0, 1);
  EXPECT_DOUBLE_EQ(point_edge_distance_squared(p, q, q), (p - q).squaredNorm());
  EXPECT_DOUBLE_EQ(point_triangle_distance_squared(p, q, q, q), (p - q).squaredNorm());
  EXPECT_DOUBLE_EQ(edge_edge_distance_squared(p, p, q, q), (p - q).squaredNorm());
  EXPECT_DOUBLE_EQ(edge_edge_distance_squared(p, p, q, Vec3(2, 0, 1)),
                   point_edge_distance_squared(p, q, Vec3(2, 0, 1)));
}

}  // namespace
}  // namespace animkit
