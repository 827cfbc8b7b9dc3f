// Contact (contact.h): no step ever produces an intersection, checked on every frame by an
// exact test that shares no code with the solver (CGAL, tests/support/intersection_audit.h);
// the term's gradient against finite differences; pins hold; bad settings are refused.
#include "animkit/cloth/contact.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/collision/collider_surface.h"
#include "intersection_audit.h"

namespace animkit {
namespace {

TriangleMesh cloth_mesh(const ClothSimulator& sim) {
  TriangleMesh mesh;
  for (int i = 0; i < sim.model().particle_count(); ++i)
    mesh.vertices.push_back(sim.state().position(i));
  mesh.triangles = sim.model().triangles;
  return mesh;
}

TriangleMesh sphere(const Vec3& center, double radius) {
  TriangleMesh mesh = collider_surface(SphereShape{radius}, 3);
  for (Vec3& v : mesh.vertices) v += center;
  return mesh;
}

// A free cotton sheet (side 0.6 m, `cells` per side) centred above the origin at `height`.
ClothDesc cotton_sheet(int cells, double height, const Vec3& velocity) {
  GridClothOptions grid{.cells = cells, .size = 0.6, .gravity = 9.81};
  grid.height = height;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) {
    p.position.x() -= 0.3;
    p.velocity = velocity;
    p.pinned = false;
  }
  return desc;
}

SimulationOptions multigrid_newton(double tolerance) {
  SimulationOptions options{find_integrator("implicit-multigrid")->defaults, 0};
  set_tolerance(options.integrator, tolerance);
  // An impact at 20 m/s takes Newton about 70 iterations: CCD shortens every step while new
  // parts of the sheet reach the ball.
  std::get<NewtonSettings>(options.integrator).max_iterations = 500;
  return options;
}

TEST(Contact, AClothThrownAtASphereAt20MetresPerSecondNeverPassesThrough) {
  // dt = 1/30 s at 20 m/s: each step's prediction lies 67 cm on, past the whole sphere. The
  // sheet meets the ball in the first step and wraps round it in the next two (the steps
  // where it could tunnel); then it lies on the ball and slides off it slowly, for about 27
  // frames. Ten frames keep the impact and seven frames of resting contact, in 56% of the time
  // of all 30 (measured in Release; the sanitizer build's slowest test).
  auto sim =
      ClothSimulator::create(cotton_sheet(12, 0.45, Vec3(0.0, -20.0, 0.0)), multigrid_newton(1e-4));
  ASSERT_TRUE(sim) << sim.error().message;
  const TriangleMesh ball = sphere(Vec3::Zero(), 0.25);
  auto contact =
      ContactTerm::create(std::make_shared<const ClothModel>(sim->model()), {.thickness = 2e-3},
                          {.meshes = {ball}, .ground_height = -0.5});
  ASSERT_TRUE(contact) << contact.error().message;
  ASSERT_TRUE(sim->add_energy_term(*contact));
  int converged = 0, most_contacts = 0;
  constexpr int kFrames = 10;
  for (int frame = 1; frame <= kFrames; ++frame) {
    const auto report = sim->step(1.0 / 30.0);
    ASSERT_TRUE(report) << report.error().message;
    converged += report->converged ? 1 : 0;
    const TriangleMesh cloth = cloth_mesh(*sim);
    ASSERT_FALSE(audit::meshes_intersect(cloth, ball)) << "frame " << frame;
    ASSERT_EQ(audit::count_self_intersections(cloth), 0) << "frame " << frame;
    for (const Vec3& v : cloth.vertices) {
      ASSERT_GT(v.norm(), 0.25 * 0.98) << "a particle inside the ball at frame " << frame;
      ASSERT_GT(v.y(), -0.5) << "a particle below the ground at frame " << frame;
    }
    most_contacts = std::max(most_contacts, (*contact)->stats(sim->state().positions).active_pairs);
    if (frame == 1) {
      EXPECT_LT(report->step_bound_min, 1.0);  // CCD held the first step back
    }
  }
  EXPECT_EQ(converged, kFrames);
  EXPECT_GT(most_contacts, 20);  // it did hit the ball (then slides off it, frictionless)
}

// Either barrier Hessian (ContactSettings::hessian) lets the sheet settle the same way.
class ContactHessian : public ::testing::TestWithParam<BarrierHessian> {};

TEST_P(ContactHessian, ASheetSettlesOnTheGroundWithinItsThicknessAndPinsHold) {
  ClothDesc desc = cotton_sheet(8, 0.05, Vec3::Zero());
  desc.particles[0].pinned = true;  // one corner held 5 cm up
  const Vec3 pinned = desc.particles[0].position;
  auto sim = ClothSimulator::create(desc, multigrid_newton(1e-4));
  ASSERT_TRUE(sim);
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                                     {.thickness = 2e-3, .hessian = GetParam()},
                                     {.meshes = {}, .ground_height = 0.0});
  ASSERT_TRUE(contact);
  ASSERT_TRUE(sim->add_energy_term(*contact));
  int converged = 0;
  for (int frame = 0; frame < 60; ++frame) {
    const auto report = sim->step(1.0 / 60.0);
    ASSERT_TRUE(report);
    converged += report->converged ? 1 : 0;
  }
  EXPECT_EQ(converged, 60);
  EXPECT_EQ(sim->state().position(0), pinned);
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < sim->model().particle_count(); ++i)
    lowest = std::min(lowest, sim->state().position(i).y());
  EXPECT_GT(lowest, 0.0);
  EXPECT_LT(lowest, 2e-3);  // resting within the barrier's reach
}

INSTANTIATE_TEST_SUITE_P(BothHessians, ContactHessian,
                         ::testing::Values(BarrierHessian::projected, BarrierHessian::gauss_newton,
                                           BarrierHessian::adaptive),
                         [](const ::testing::TestParamInfo<BarrierHessian>& hessian) {
                           return std::string(barrier_hessian_name(hessian.param));
                         });

// The Gauss-Newton choice assembles, pair by pair, exactly contact_barrier_gauss_newton_hessian
// times kappa: a positive semi-definite matrix that is not the projected one. The adaptive
// choice gives Gauss-Newton's until CCD freezes a step, then the projected one.
TEST(Contact, GaussNewtonHessianIsPsdUnlikeTheProjectedOneAndAdaptiveSwitchesOnAFrozenStep) {
  auto sim = ClothSimulator::create(cotton_sheet(4, 0.0012, Vec3::Zero()), {});
  ASSERT_TRUE(sim);
  const auto model = std::make_shared<const ClothModel>(sim->model());
  const int n = model->particle_count();
  Eigen::VectorXd x = sim->state().positions;
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 2e-4 * std::sin(1.9 * static_cast<double>(k));
  auto dense_hessian = [&](BarrierHessian kind, double frozen_step = 0.0) {
    auto contact = ContactTerm::create(
        model, {.thickness = 2e-3, .hessian = kind},
        {.meshes = {sphere(Vec3(0.0, -0.2985, 0.0), 0.3)}, .ground_height = 0.0});
    EXPECT_TRUE(contact);
    ContactTerm& term = **contact;
    term.prepare(sim->state(), 1.0 / 60.0);
    if (frozen_step > 0.0) {
      // A step straight down through the ball: CCD admits almost none of it.
      Eigen::VectorXd down = Eigen::VectorXd::Zero(x.size());
      for (int i = 0; i < n; ++i) down[3 * i + 1] = -frozen_step;
      EXPECT_LT(term.max_step(x, down), kFrozenStepFraction);
    }
    term.update(x);
    EXPECT_GT(term.stats(x).active_pairs, 0);
    std::vector<HessianBlock> blocks;
    term.add_hessian(x, true, blocks);
    Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(3 * n, 3 * n);
    for (const HessianBlock& b : blocks) {
      dense.block<3, 3>(3 * b.row, 3 * b.col) += b.value;
      if (b.row != b.col) dense.block<3, 3>(3 * b.col, 3 * b.row) += b.value.transpose();
    }
    return dense;
  };
  const Eigen::MatrixXd gauss_newton = dense_hessian(BarrierHessian::gauss_newton);
  const Eigen::MatrixXd projected = dense_hessian(BarrierHessian::projected);
  // Adaptive: Gauss-Newton's until a step is frozen, the projected one from then on.
  EXPECT_EQ(dense_hessian(BarrierHessian::adaptive), gauss_newton);
  EXPECT_EQ(dense_hessian(BarrierHessian::adaptive, 1e3), projected);
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(gauss_newton);
  ASSERT_GT(eigen.eigenvalues().maxCoeff(), 0.0);
  EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-9 * eigen.eigenvalues().maxCoeff());
  EXPECT_GT((gauss_newton - projected).norm(), 1e-6 * projected.norm());
}

TEST(Contact, GradientMatchesFiniteDifferences) {
  auto sim = ClothSimulator::create(cotton_sheet(4, 0.0012, Vec3::Zero()), {});
  ASSERT_TRUE(sim);
  const auto model = std::make_shared<const ClothModel>(sim->model());
  // A ball just under the sheet's middle and the ground just under it: pairs of every kind.
  auto contact =
      ContactTerm::create(model, {.thickness = 2e-3},
                          {.meshes = {sphere(Vec3(0.0, -0.2985, 0.0), 0.3)}, .ground_height = 0.0});
  ASSERT_TRUE(contact);
  ContactTerm& term = **contact;
  term.prepare(sim->state(), 1.0 / 60.0);
  Eigen::VectorXd x = sim->state().positions;
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 2e-4 * std::sin(1.9 * static_cast<double>(k));
  term.update(x);
  ASSERT_GT(term.stats(x).active_pairs, 0);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
  term.add_gradient(x, gradient);
  ASSERT_GT(gradient.norm(), 0.0);
  const double eps = 1e-8;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Eigen::VectorXd plus = x, minus = x;
    plus[k] += eps;
    minus[k] -= eps;
    const double fd = (term.value(plus) - term.value(minus)) / (2 * eps);
    EXPECT_NEAR(gradient[k], fd, 1e-4 * (std::abs(fd) + 1e-3 * gradient.norm())) << k;
  }
}

TEST(Contact, BadSettingsAreRefusedByName) {
  auto sim = ClothSimulator::create(make_grid_cloth({.cells = 3}), {});
  ASSERT_TRUE(sim);
  const auto model = std::make_shared<const ClothModel>(sim->model());
  EXPECT_EQ(ContactTerm::create(model, {.thickness = 0.0}, {}).error().message,
            "contact thickness must be > 0 m and at most 1e+06 m, got 0");
  EXPECT_EQ(ContactTerm::create(model, {.stiffness = -1.0}, {}).error().message,
            "contact stiffness (J/m^4, 0: automatic) must be between 0 and 1e+20, got -1");
  EXPECT_EQ(ContactTerm::create(model, {.stiffness = 1e300}, {}).error().message,
            "contact stiffness (J/m^4, 0: automatic) must be between 0 and 1e+20, got 1e+300");
  EXPECT_EQ(ContactTerm::create(model, {.min_separation = 1.0}, {}).error().message,
            "contact minimum separation must be in (0, 1), got 1");
  EXPECT_EQ(ContactTerm::create(model, {}, {.meshes = {TriangleMesh{}}, .ground_height = {}})
                .error()
                .message,
            "obstacle 0: the mesh has no triangles");
}

}  // namespace
}  // namespace animkit
