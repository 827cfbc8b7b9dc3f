#include "animkit/collision/ccd.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "animkit/collision/distance_type.h"
#include "stencil_checks.h"

namespace animkit {
namespace {

using test::RandomPoints;
using Four = std::array<Vec3, 4>;

enum class Pair { kPointTriangle, kEdgeEdge };

struct Motion {
  Pair pair = Pair::kPointTriangle;
  Four start, end;
};

Four at(const Motion& m, double t) {
  Four x;
  for (int i = 0; i < 4; ++i) x[i] = m.start[i] + t * (m.end[i] - m.start[i]);
  return x;
}

double gap(const Motion& m, double t, double thickness) {
  const Four x = at(m, t);
  const double d2 = m.pair == Pair::kPointTriangle
                        ? point_triangle_distance_squared(x[0], x[1], x[2], x[3])
                        : edge_edge_distance_squared(x[0], x[1], x[2], x[3]);
  return std::sqrt(d2) - thickness;
}

CcdResult run_ccd(const Motion& m, const AdditiveCcdSettings& settings) {
  const auto result = m.pair == Pair::kPointTriangle ? point_triangle_ccd(m.start, m.end, settings)
                                                     : edge_edge_ccd(m.start, m.end, settings);
  EXPECT_TRUE(result.has_value());
  return result.value_or(CcdResult{});
}

// Brute force along the motion: the gap sampled at kSamples + 1 times; the first sample below
// `level` is refined by bisection against its predecessor. Returns 2 (past the step) when no
// sample is below. Sampling can only miss a dip (making the answer later), never invent one.
constexpr int kSamples = 20000;

struct Sampled {
  std::vector<double> gaps;
  double min_gap = 0.0;
};

Sampled sample(const Motion& m, double thickness) {
  Sampled s;
  s.gaps.resize(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) s.gaps[i] = gap(m, double(i) / kSamples, thickness);
  s.min_gap = *std::min_element(s.gaps.begin(), s.gaps.end());
  return s;
}

double first_time_below(const Motion& m, const Sampled& s, double level, double thickness) {
  for (int i = 1; i <= kSamples; ++i) {
    if (s.gaps[i] >= level) continue;
    double lo = double(i - 1) / kSamples, hi = double(i) / kSamples;
    for (int k = 0; k < 60; ++k) {
      const double mid = 0.5 * (lo + hi);
      (gap(m, mid, thickness) < level ? hi : lo) = mid;
    }
    return lo;
  }
  return 2.0;
}

// The largest relative speed of two points of the pair (the Lipschitz constant of the gap),
// for the sampling's resolution: between samples the gap dips at most speed / kSamples / 2.
double speed_bound(const Motion& m) {
  double speed = 0.0;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const bool same_side =
          m.pair == Pair::kPointTriangle ? (i == 0) == (j == 0) : (i < 2) == (j < 2);
      if (!same_side) {
        speed = std::max(speed, ((m.end[i] - m.start[i]) - (m.end[j] - m.start[j])).norm());
      }
    }
  }
  return speed;
}

// The properties every CCD answer must have, checked against the brute force:
// - safe: the gap at t* is at least s G0, and nowhere on [0, t*] below 0.5 s G0 (the guarantee is
//   0.55 s G0), so t* is never past the first contact;
// - not absurdly conservative: t* >= 0.5 of the first time the gap reaches s G0 when that time
//   is in (0.05, 1); and the whole step when the gap provably stays above s G0.
// Returns t* / T_s when the efficiency bound was checked, else -1.
double check_against_brute_force(const Motion& m, const AdditiveCcdSettings& settings) {
  const double xi = settings.thickness, s = settings.separation_fraction;
  const CcdResult ccd = run_ccd(m, settings);
  const Sampled sampled = sample(m, xi);
  const double gap0 = sampled.gaps[0];
  const double t_half = first_time_below(m, sampled, 0.5 * s * gap0, xi);
  const double t_s = first_time_below(m, sampled, s * gap0, xi);
  EXPECT_LT(ccd.time_of_impact, t_half);
  EXPECT_GE(gap(m, ccd.time_of_impact, xi), s * gap0 * (1.0 - 1e-9));
  EXPECT_GE(ccd.time_of_impact, 0.0);
  EXPECT_LE(ccd.time_of_impact, 1.0);
  if (t_s > 0.05 && t_s < 1.0) {
    EXPECT_GE(ccd.time_of_impact, 0.5 * t_s) << "T_s " << t_s;
  }
  const double dip = 0.5 * speed_bound(m) / kSamples;  // the most sampling can miss
  if (sampled.min_gap - dip > s * gap0) {
    EXPECT_EQ(ccd.time_of_impact, 1.0);
    EXPECT_FALSE(ccd.collides);
  }
  return t_s > 0.05 && t_s < 1.0 ? ccd.time_of_impact / t_s : -1.0;
}

// A motion whose primitives touch at time `contact`: the configuration at `contact` is given
// (touching), velocities are random; start and end are extrapolated from it.
Motion touching_at(Pair pair, const Four& contact_configuration, const Four& velocity,
                   double contact) {
  Motion m;
  m.pair = pair;
  for (int i = 0; i < 4; ++i) {
    m.start[i] = contact_configuration[i] - contact * velocity[i];
    m.end[i] = m.start[i] + velocity[i];
  }
  return m;
}

// Point inside (or on the boundary of, if `on_edge`) a random triangle; edges crossing.
Four touching_point_triangle(RandomPoints& random, bool on_edge) {
  Four x = random.points<4>();
  double b1 = random.uniform(0.05, 0.9), b2 = random.uniform(0.05, 0.9);
  if (b1 + b2 > 0.95) b1 = 0.95 - b2;
  if (on_edge) b2 = 0.0;
  x[0] = x[1] + b1 * (x[2] - x[1]) + b2 * (x[3] - x[1]);
  return x;
}

Four touching_edges(RandomPoints& random) {
  Four x = random.points<4>();
  const Vec3 meet = x[0] + random.uniform(0.1, 0.9) * (x[1] - x[0]);
  const Vec3 direction = random.point().normalized();
  x[2] = meet - random.uniform(0.1, 1.0) * direction;
  x[3] = meet + random.uniform(0.1, 1.0) * direction;
  return x;
}

TEST(Ccd, AgreesWithBruteForceOnRandomMotions) {
  RandomPoints random(41);
  double worst_ratio = 1.0;
  int efficiency_checks = 0;
  const auto record = [&](double ratio) {
    if (ratio < 0.0) return;
    ++efficiency_checks;
    worst_ratio = std::min(worst_ratio, ratio);
  };
  for (double s : {0.1, 0.01}) {
    AdditiveCcdSettings settings;
    settings.separation_fraction = s;
    for (int trial = 0; trial < 100; ++trial) {
      for (Pair pair : {Pair::kPointTriangle, Pair::kEdgeEdge}) {
        // Touching at a random time inside the step, and unconstrained random motions.
        const Four contact = pair == Pair::kPointTriangle ? touching_point_triangle(random, false)
                                                          : touching_edges(random);
        const Motion hit = touching_at(pair, contact, random.points<4>(), random.uniform(0.2, 0.9));
        record(check_against_brute_force(hit, settings));
        Motion free{pair, random.points<4>(), random.points<4>()};
        record(check_against_brute_force(free, settings));
      }
    }
  }
  EXPECT_GT(efficiency_checks, 200);  // of 400 motions: the bound is exercised
  RecordProperty("worst_ratio", std::to_string(worst_ratio));
}

// Grazing: the point's velocity relative to the triangle almost in the triangle's plane;
// parallel edges approaching each other (they stay parallel: each edge only translates); a
// point moving in the triangle's plane into an edge.
TEST(Ccd, AgreesWithBruteForceOnDegenerateMotions) {
  RandomPoints random(42);
  const AdditiveCcdSettings settings;
  for (int trial = 0; trial < 60; ++trial) {
    Four x = touching_point_triangle(random, false);
    const Vec3 normal = (x[2] - x[1]).cross(x[3] - x[1]).normalized();
    Vec3 tangent = random.point().cross(normal).normalized();
    Four velocity = {tangent + 1e-3 * normal, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
    check_against_brute_force(touching_at(Pair::kPointTriangle, x, velocity, 0.6), settings);

    Four edges = random.points<4>();
    edges[3] = edges[2] + 0.8 * (edges[1] - edges[0]);  // parallel
    edges[2] += 0.3 * (edges[1] - edges[0]);            // overlapping
    const Vec3 shift = random.point();
    Four parallel_start = edges, parallel_end = edges;
    parallel_end[2] += shift;
    parallel_end[3] += shift;
    check_against_brute_force(Motion{Pair::kEdgeEdge, parallel_start, parallel_end}, settings);
    const Vec3 across = (edges[1] - edges[0]).cross(random.point()).normalized();
    const Four toward = {Vec3::Zero(), Vec3::Zero(), across, across};
    Four touching = edges;
    touching[2] = touching[0] + 0.2 * (edges[1] - edges[0]);
    touching[3] = touching[0] + 1.1 * (edges[1] - edges[0]);
    check_against_brute_force(touching_at(Pair::kEdgeEdge, touching, toward, 0.5), settings);

    Four in_plane = touching_point_triangle(random, true);  // on edge ab at the contact
    const Vec3 n = (in_plane[2] - in_plane[1]).cross(in_plane[3] - in_plane[1]);
    const Vec3 inward = n.cross(in_plane[2] - in_plane[1]).normalized();
    const Four slide = {inward, 0.2 * (in_plane[2] - in_plane[1]), Vec3::Zero(), Vec3::Zero()};
    check_against_brute_force(touching_at(Pair::kPointTriangle, in_plane, slide, 0.4), settings);
  }
}

TEST(Ccd, StillOrTranslatingPairsTakeTheWholeStep) {
  const Four x = {Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  Four moved = x;
  for (Vec3& v : moved) v += Vec3(3, -2, 7);
  for (const Four& end : {x, moved}) {
    const CcdResult result = point_triangle_ccd(x, end).value();
    EXPECT_EQ(result.time_of_impact, 1.0);
    EXPECT_FALSE(result.collides);
    EXPECT_EQ(result.iterations, 1);
  }
}

TEST(Ccd, PrimitivesAlreadyClose) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  for (double height : {1e-9, 1e-6}) {
    const Four start = {Vec3(0.2, 0.2, height), a, b, c};
    // Head-on at unit speed: contact at t = height. C-IPC's first step goes to (1 - s) of it.
    const CcdResult toward =
        point_triangle_ccd(start, {Vec3(0.2, 0.2, height - 1.0), a, b, c}).value();
    EXPECT_TRUE(toward.collides);
    EXPECT_LT(toward.time_of_impact, height);
    EXPECT_GE(toward.time_of_impact, 0.89 * height);
    const CcdResult away = point_triangle_ccd(start, {Vec3(0.2, 0.2, 1.0), a, b, c}).value();
    EXPECT_EQ(away.time_of_impact, 1.0);
  }
  const Four touching = {Vec3(0.2, 0.2, 0.0), a, b, c};
  const CcdResult stuck = point_triangle_ccd(touching, touching).value();
  EXPECT_EQ(stuck.time_of_impact, 0.0);
  EXPECT_TRUE(stuck.collides);
}

TEST(Ccd, KeepsTheThickness) {
  RandomPoints random(43);
  AdditiveCcdSettings settings;
  settings.thickness = 0.05;
  for (int trial = 0; trial < 50; ++trial) {
    Four x = touching_edges(random);
    const Vec3 across = (x[1] - x[0]).cross(x[3] - x[2]).normalized();
    for (int i = 0; i < 4; ++i) x[i] += (i < 2 ? 0.1 : -0.1) * across;  // 0.2 apart
    const Four toward = {-across, -across, across, across};
    check_against_brute_force(touching_at(Pair::kEdgeEdge, x, toward, 0.0), settings);
  }
}

// Motion across the gap (cloth sliding over a surface): once the walk proves long, the
// separating direction clears the rest of the step at once, where the Lipschitz walk alone
// takes a thousand steps of 0.9 * 1e-3.
TEST(Ccd, ASlideAlongTheFaceEndsInFewSteps) {
  const Four start = {Vec3(-0.5, 0.1, 1e-3), Vec3(-1, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  for (const Vec3& slide : {Vec3(1.0, 0.0, 0.0), Vec3(0.3, 0.8, -5e-4), Vec3(-0.4, 0.2, 0.0)}) {
    Four end = start;
    end[0] += slide;  // the last slide descends to half the height: still above 10% of it
    const CcdResult result = point_triangle_ccd(start, end).value();
    EXPECT_EQ(result.time_of_impact, 1.0);
    EXPECT_FALSE(result.collides);
    EXPECT_LE(result.iterations, 40);
  }
  // The Lipschitz walk alone, as the collider's advance uses it: a thousand steps.
  Four end = start;
  end[0].x() += 1.0;
  AdditiveCcdSettings walk_only;
  walk_only.along_separation = false;
  const CcdResult walked = point_triangle_ccd(start, end, walk_only).value();
  EXPECT_EQ(walked.time_of_impact, 1.0);
  EXPECT_GT(walked.iterations, 500);
  // Two edges crossing at 1e-3, one sliding along the other.
  const Four edges = {Vec3(-1, 0, 1e-3), Vec3(1, 0, 1e-3), Vec3(0, -1, 0), Vec3(0, 1, 0)};
  Four slid = edges;
  slid[0].x() += 0.5, slid[1].x() += 0.5;
  const CcdResult crossing = edge_edge_ccd(edges, slid).value();
  EXPECT_EQ(crossing.time_of_impact, 1.0);
  EXPECT_LE(crossing.iterations, 40);
}

TEST(Ccd, IterationCapStopsEarlyButSafely) {
  // The point slides 1 along the face's edge ab at height 1e-3 while the face tilts about that
  // edge, its far vertex c rising 0.1: the gap under the point halves and never closes, but
  // every bound the walk has (c's rise, the slide) allows only about 1e-2 of the step at a time.
  const Four start = {Vec3(-0.5, 0.01, 1e-3), Vec3(-1, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  Four end = start;
  end[0].x() += 1.0;
  end[3].z() += 0.1;
  AdditiveCcdSettings settings;
  const CcdResult full = point_triangle_ccd(start, end, settings).value();
  EXPECT_EQ(full.time_of_impact, 1.0);
  EXPECT_GT(full.iterations, 100);
  settings.max_iterations = 10;
  const CcdResult capped = point_triangle_ccd(start, end, settings).value();
  EXPECT_TRUE(capped.collides);
  EXPECT_GT(capped.time_of_impact, 0.0);
  EXPECT_LT(capped.time_of_impact, 0.1);
  EXPECT_EQ(capped.iterations, 10);
}

TEST(Ccd, PointEdgeAndPointPointAreSafe) {
  RandomPoints random(44);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<Vec3, 3> start = random.points<3>(), end = random.points<3>();
    const CcdResult result = point_edge_ccd(start, end).value();
    const double gap0 = std::sqrt(point_edge_distance_squared(start[0], start[1], start[2]));
    for (int i = 0; i <= 1000; ++i) {
      const double t = result.time_of_impact * i / 1000;
      const auto x = [&](int k) { return Vec3(start[k] + t * (end[k] - start[k])); };
      EXPECT_GE(std::sqrt(point_edge_distance_squared(x(0), x(1), x(2))), 0.5 * 0.1 * gap0);
    }
  }
  // Head-on points 1 apart closing at speed 2: contact at 0.5, first step (1 - s) of it.
  const CcdResult head_on =
      point_point_ccd({Vec3(0, 0, 0), Vec3(1, 0, 0)}, {Vec3(1, 0, 0), Vec3(0, 0, 0)}).value();
  EXPECT_NEAR(head_on.time_of_impact, 0.45, 1e-12);
  EXPECT_TRUE(head_on.collides);
}

TEST(Ccd, RejectsInvalidSettingsAndCoordinates) {
  const Four x = {Vec3(0, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  AdditiveCcdSettings settings;
  settings.separation_fraction = 1.0;
  EXPECT_EQ(point_triangle_ccd(x, x, settings).error().message,
            "CCD separation fraction must be in (0, 1), got 1");
  settings = {};
  settings.thickness = -1e-3;
  EXPECT_EQ(edge_edge_ccd(x, x, settings).error().message,
            "CCD thickness must be finite and >= 0, got -0.001");
  settings = {};
  settings.max_time = 0.0;
  EXPECT_EQ(point_triangle_ccd(x, x, settings).error().message,
            "CCD max time must be in (0, 1], got 0");
  settings = {};
  settings.max_iterations = 0;
  EXPECT_EQ(point_triangle_ccd(x, x, settings).error().message,
            "CCD max iterations must be >= 1, got 0");
  Four bad = x;
  bad[2].y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(point_triangle_ccd(x, bad).error().message, "CCD vertex 2 has a non-finite coordinate");
}

}  // namespace
}  // namespace animkit
