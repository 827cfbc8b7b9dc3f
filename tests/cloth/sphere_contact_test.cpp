// A sphere collider's exact surface in contact (contact_pair.h, "sphere"): its centre against
// each cloth triangle with its radius as the pair's thickness. The barrier's derivatives in the
// triangle's face, edge and vertex regions against central finite differences; Gauss-Newton is
// the projected Hessian at a vertex and misses the turn into the sphere elsewhere; the broad
// phase finds the centre's pairs within its radius; CCD stops a triangle short of the surface;
// friction feels the sphere's spin at its surface, though its centre stays put.
// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's eigensolver is inlined with
// -march=native (a false positive in the compiler's own headers, see psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "../../src/cloth/contact/contact_candidates.h"
#include "../../src/cloth/contact/contact_pair.h"
#include "animkit/cloth/cloth_world.h"
#include "animkit/collision/distance_type.h"
#include "animkit/collision/psd_projection.h"
#include "animkit/io/cloth_scene_file.h"

namespace animkit {
namespace {
// Names of this file's own (the unit tests compile in unity batches).
namespace sphere_contact_test {

constexpr double kDhat = 0.1;    // activation distance (m); the barrier takes its square
constexpr double kRadius = 0.5;  // the sphere's

LogBarrier barrier() {
  return *LogBarrier::create(kDhat * kDhat);
}

// The centre (slot 0, an obstacle vertex) and a cloth triangle (slots 1 to 3).
ContactPair sphere_pair() {
  ContactPair pair;
  pair.kind = ContactKind::point_triangle;
  pair.vertices = {3, 0, 1, 2};
  pair.thickness = kRadius;
  return pair;
}

// The triangle (0, 0, 0), (1, 0, 0), (0, 0, 1) under a centre whose closest point on it is
// `closest`, reached along `direction` (unit) at a gap of `gap` from the sphere's surface.
std::array<Vec3, 4> around(const Vec3& closest, const Vec3& direction, double gap) {
  return {closest + (kRadius + gap) * direction, Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)};
}

// The three regions: over the face, beside the edge (1, 0, 0)-(0, 0, 1), beyond the corner.
std::vector<std::array<Vec3, 4>> regions(double gap) {
  return {around(Vec3(0.3, 0, 0.2), Vec3::UnitY(), gap),
          around(Vec3(0.5, 0, 0.5), Vec3(1, 1, 1).normalized(), gap),
          around(Vec3(0, 0, 0), Vec3(-1, 2, -1).normalized(), gap)};
}

TEST(SphereContact, DerivativesMatchFiniteDifferencesInEveryRegion) {
  const ContactPair pair = sphere_pair();
  const LogBarrier b = barrier();
  for (const double gap : {0.01, 0.05}) {
    for (const std::array<Vec3, 4>& p : regions(gap)) {
      // The pair's distance is the gap to the sphere's surface.
      EXPECT_NEAR(contact_distance_squared(pair, p, 0.0), gap * gap, 1e-12);
      const StencilDerivatives<4> exact = contact_barrier_derivatives(pair, p, 0.0, b, false);
      EXPECT_NEAR(exact.value, b.value(gap * gap), 1e-9 * exact.value);
      const double eps = 1e-7;
      for (int k = 0; k < 12; ++k) {
        std::array<Vec3, 4> plus = p, minus = p;
        plus[k / 3][k % 3] += eps;
        minus[k / 3][k % 3] -= eps;
        const double fd =
            (contact_barrier(pair, plus, 0.0, b) - contact_barrier(pair, minus, 0.0, b)) /
            (2 * eps);
        EXPECT_NEAR(exact.gradient[k], fd, 1e-5 * (std::abs(fd) + 1e-6)) << "dof " << k;
        const auto g_plus = contact_barrier_derivatives(pair, plus, 0.0, b, false).gradient;
        const auto g_minus = contact_barrier_derivatives(pair, minus, 0.0, b, false).gradient;
        const Eigen::Matrix<double, 12, 1> column = (g_plus - g_minus) / (2 * eps);
        EXPECT_LT((exact.hessian.col(k) - column).norm(), 1e-4 * (column.norm() + 1e-6))
            << "Hessian column " << k << ", gap " << gap;
      }
      // The gradient alone is the same.
      EXPECT_LT((contact_barrier_gradient(pair, p, 0.0, b) - exact.gradient).norm(),
                1e-12 * exact.gradient.norm());
    }
  }
}

TEST(SphereContact, InsideTheSphereIsContact) {
  const std::array<Vec3, 4> p = around(Vec3(0.3, 0, 0.2), Vec3::UnitY(), -0.01);
  EXPECT_EQ(contact_distance_squared(sphere_pair(), p, 0.0), 0.0);
  EXPECT_EQ(contact_barrier(sphere_pair(), p, 0.0, barrier()), INFINITY);
}

// The cloth's 9 x 9 block (the centre is no unknown).
Eigen::Matrix<double, 9, 9> cloth_block(const Eigen::Matrix<double, 12, 12>& hessian) {
  return hessian.bottomRightCorner<9, 9>();
}

TEST(SphereContact, GaussNewtonIsTheProjectedHessianOnlyAtAVertex) {
  const ContactPair pair = sphere_pair();
  const LogBarrier b = barrier();
  const std::vector<std::array<Vec3, 4>> p = regions(0.03);
  for (std::size_t region = 0; region < p.size(); ++region) {
    const bool vertex = region == 2;
    EXPECT_EQ(gauss_newton_suffices(pair, p[region]), vertex) << "region " << region;
    const auto projected =
        cloth_block(contact_barrier_derivatives(pair, p[region], 0.0, b).hessian);
    const auto gn = cloth_block(contact_barrier_gauss_newton_hessian(pair, p[region], 0.0, b));
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 9, 9>> eig(projected);
    EXPECT_GT(eig.eigenvalues().minCoeff(), -1e-9 * projected.norm());
    // The cloth's block of the exact Hessian, projected (by the edge's block alone where the
    // nearest point is on an edge: the same matrix).
    const Eigen::Matrix<double, 9, 9> direct = project_to_psd(
        cloth_block(contact_barrier_derivatives(pair, p[region], 0.0, b, false).hessian));
    EXPECT_LT((projected - direct).norm(), 1e-9 * direct.norm()) << "region " << region;
    if (vertex) {
      EXPECT_LT((projected - gn).norm(), 1e-9 * gn.norm());
      continue;
    }
    // Turning the triangle about its closest point brings it closer to the sphere: the
    // projected Hessian resists that, Gauss-Newton (rank one, along the normal) does not.
    const Vec3 closest = region == 0 ? Vec3(0.3, 0, 0.2) : Vec3(0.5, 0, 0.5);
    // Across the normal: for the edge, also across the edge (turning about the edge's own
    // line moves nothing that counts).
    const Vec3 axis =
        region == 0 ? Vec3::UnitX() : Vec3(1, 1, 1).cross(Vec3(-1, 0, 1)).normalized();
    Eigen::Matrix<double, 9, 1> turn;
    for (int v = 0; v < 3; ++v) turn.segment<3>(3 * v) = axis.cross(p[region][v + 1] - closest);
    EXPECT_GT(turn.dot(projected * turn), 1e3 * std::abs(turn.dot(gn * turn)))
        << "region " << region;
  }
}

// Over a face the projection works on the five directions the gap depends on: the same matrix
// as projecting the whole 9 x 9 block, for triangles of any shape, size and pose.
TEST(SphereContact, AFacesFiveDirectionsProjectAsTheWholeBlock) {
  const ContactPair pair = sphere_pair();
  const LogBarrier b = barrier();
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto vec = [&] { return Vec3(unit(random), unit(random), unit(random)); };
  int compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::array<Vec3, 4> p;
    for (int v = 1; v < 4; ++v) p[v] = vec();
    const Vec3 normal = (p[2] - p[1]).cross(p[3] - p[1]).normalized();
    Eigen::Vector3d weight = (vec().array() + 1.5).matrix();  // inside: all positive
    weight /= weight.sum();
    const Vec3 foot = weight[0] * p[1] + weight[1] * p[2] + weight[2] * p[3];
    p[0] = foot + (kRadius + 0.05 * kDhat * (1.0 + unit(random))) * normal;
    if (point_triangle_distance_type(p[0], p[1], p[2], p[3]) !=
        PointTriangleDistanceType::kInterior)
      continue;
    const auto projected = cloth_block(contact_barrier_derivatives(pair, p, 0.0, b).hessian);
    const Eigen::Matrix<double, 9, 9> direct =
        project_to_psd(cloth_block(contact_barrier_derivatives(pair, p, 0.0, b, false).hessian));
    EXPECT_LT((projected - direct).norm(), 1e-9 * direct.norm()) << "trial " << trial;
    ++compared;
  }
  EXPECT_GT(compared, 150);
}

// One cloth triangle (particles 0 to 2) and a sphere of radius 0.5 m centred 1 m above it.
struct Scene {
  ContactGeometry geometry;
  Eigen::VectorXd cloth = Eigen::VectorXd(9);
};

Scene sphere_over_triangle() {
  ClothModel model;
  model.mass = {1.0, 1.0, 1.0};
  model.pinned = {0, 0, 0};
  model.triangles = {{0, 1, 2}};
  TriangleMesh centre{{Vec3(0.2, 1.0, 0.2)}, {}};
  Scene scene{build_contact_geometry(model, {centre}, false, {kRadius}).value()};
  scene.cloth << 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0;
  return scene;
}

TEST(SphereContact, TheBroadPhaseReachesAsFarAsTheRadius) {
  const Scene scene = sphere_over_triangle();
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  // 0.5 m from the sphere's surface: beyond a 0.4 m reach, within a 0.6 m one.
  ASSERT_TRUE(finder.gather(scene.geometry, scene.cloth, nullptr, 0.4, std::nullopt, pairs));
  EXPECT_TRUE(pairs.empty());
  ASSERT_TRUE(finder.gather(scene.geometry, scene.cloth, nullptr, 0.6, std::nullopt, pairs));
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].vertices, (std::array<int, 4>{3, 0, 1, 2}));
  EXPECT_EQ(pairs[0].thickness, kRadius);
}

TEST(SphereContact, CcdStopsATriangleShortOfTheSurface) {
  const Scene scene = sphere_over_triangle();
  // Lifted 2 m, the triangle would pass through the sphere; its start is 0.5 m off it.
  Eigen::VectorXd step = Eigen::VectorXd::Zero(9);
  for (int v = 0; v < 3; ++v) step[3 * v + 1] = 2.0;
  ContactPairFinder finder;
  std::vector<ContactPair> pairs;
  ASSERT_TRUE(finder.gather(scene.geometry, scene.cloth, &step, 0.1, std::nullopt, pairs));
  ASSERT_FALSE(pairs.empty());
  const double bound = earliest_contact(scene.geometry, pairs, scene.cloth, step, 0.0, 0.1, 0.1);
  // At most the 0.45 m that keeps a tenth of the gap (0.225 of the step), and most of it.
  EXPECT_LE(bound, 0.225);
  EXPECT_GT(bound, 0.2);
  std::array<Vec3, 4> p;
  p[0] = scene.geometry.obstacle_positions.head<3>();
  for (int v = 0; v < 3; ++v)
    p[v + 1] = scene.cloth.segment<3>(3 * v) + bound * step.segment<3>(3 * v);
  EXPECT_GE(std::sqrt(contact_distance_squared(pairs[0], p, 0.0)), 0.05 * (1 - 1e-9));
}

// A 0.4 m cotton sheet (6 x 6 cells) dropped 3 mm onto a ball of radius 0.15 m turning at
// 4 rad/s about y, with friction mu between them; the particles' median turn about y (rad)
// after 20 frames.
double median_turn_on_spinning_ball(double mu) {
  const std::string scene = R"({"cloth": {"grid": 6, "size": 0.4, "height": 0.153,
                                          "material": "cotton", "pins": "none",
                                          "offset": [-0.2, 0, 0]},
                               "colliders": [{"name": "ball", "radius": 0.15,
                                              "angular_velocity": [0, 4, 0],
                                              "friction": )" +
                            std::to_string(mu) + R"(}],
                               "frames": 20, "dt": 0.0333333})";
  const auto desc = parse_cloth_scene(scene, "spin.json", std::filesystem::current_path());
  EXPECT_TRUE(desc) << desc.error().message;
  if (!desc) return std::nan("");
  auto world = build_cloth_world(*desc);
  EXPECT_TRUE(world) << world.error().message;
  if (!world) return std::nan("");
  ClothSimulator& sim = world->simulator;
  const ClothState start = sim.state();
  for (int frame = 0; frame < desc->frames; ++frame) {
    const auto report = sim.step(desc->time_step);
    EXPECT_TRUE(report && report->converged) << "frame " << frame;
  }
  std::vector<double> turns;
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    const Vec3 a = start.position(i), b = sim.state().position(i);
    if (std::hypot(a.x(), a.z()) < 0.05) continue;  // near the axis: no angle to speak of
    turns.push_back(std::remainder(std::atan2(b.z(), b.x()) - std::atan2(a.z(), a.x()),
                                   2.0 * std::numbers::pi));
  }
  std::nth_element(turns.begin(), turns.begin() + turns.size() / 2, turns.end());
  return turns[turns.size() / 2];
}

TEST(SphereContact, FrictionTurnsClothWithASpinningBall) {
  // The ball turns 2.7 rad in the 20 frames; spinning about +y, x goes toward -z, so angles
  // measured as atan2(z, x) fall. Without friction the cloth does not follow.
  const double with_friction = median_turn_on_spinning_ball(0.5);
  EXPECT_LT(with_friction, -0.5);
  EXPECT_NEAR(median_turn_on_spinning_ball(0.0), 0.0, 0.02);
}

}  // namespace sphere_contact_test
}  // namespace
}  // namespace animkit
