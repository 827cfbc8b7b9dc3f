// Friction (friction.h): IPC's lagged, smoothed Coulomb friction. Its gradient and Hessian
// against finite differences; Coulomb's law on a tilted plane (sticks below atan(mu), slides
// with acceleration g (sin t - mu cos t) above); a sliding sheet stops in v^2 / (2 mu g); mu = 0
// changes no bit; pins hold; bad settings are refused by name.
// GCC 12 at -O1 warns of an uninitialized value inside Eigen's eigensolver (a false positive
// of its AVX-512 paths), as in barrier_test.
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "animkit/cloth/friction.h"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <numbers>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/collision/collider_surface.h"

namespace animkit {
namespace {

constexpr double kGravity = 9.81;
constexpr double kThickness = 2e-3;

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

SimulationOptions direct_newton(double tolerance) {
  SimulationOptions options{find_integrator("implicit-direct")->defaults, 0};
  set_tolerance(options.integrator, tolerance);
  std::get<NewtonSettings>(options.integrator).max_iterations = 300;
  return options;
}

// Down the slope of a plane tilted by t about z: s = 1 at (cos t, sin t, 0); the plane's
// normal is (-sin t, cos t, 0).
Vec3 slope_axis(double t) {
  return Vec3(std::cos(t), std::sin(t), 0.0);
}
Vec3 slope_normal(double t) {
  return Vec3(-std::sin(t), std::cos(t), 0.0);
}

// The tilted plane as an obstacle mesh: a quad of two triangles, (s, z) in [-3, 1] x [-1, 3],
// its diagonal (z = s + 2) far from where the patch slides (s in [-1.5, 0.1], z in [0.3, 0.5]).
TriangleMesh tilted_plane(double t) {
  TriangleMesh plane;
  for (const auto& [s, z] : {std::pair{-3.0, -1.0}, {1.0, -1.0}, {1.0, 3.0}, {-3.0, 3.0}})
    plane.vertices.push_back(s * slope_axis(t) + Vec3(0.0, 0.0, z));
  plane.triangles = {{0, 1, 2}, {0, 2, 3}};
  return plane;
}

// A 0.2 m cotton patch (4 x 4 cells) lying on the tilted plane at half the contact thickness,
// s in [-0.1, 0.1], z in [0.3, 0.5], at rest.
ClothDesc patch_on_slope(double t) {
  GridClothOptions grid{.cells = 4, .size = 0.2, .gravity = kGravity};
  grid.height = 0.0;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) {
    const double s = p.position.x() - 0.1, z = p.position.z() + 0.3;
    p.position = s * slope_axis(t) + Vec3(0.0, 0.0, z) + 0.5 * kThickness * slope_normal(t);
    p.velocity.setZero();
    p.pinned = false;
  }
  return desc;
}

struct SlopeRun {
  ClothSimulator sim;
  std::shared_ptr<ContactTerm> contact;
  std::shared_ptr<FrictionTerm> friction;  // null without friction
};

// A simulator of the patch on a plane tilted by t with friction mu (none: no friction term).
SlopeRun slope_run(const ClothDesc& desc, double t, std::optional<double> mu, int passes = 1) {
  auto sim = ClothSimulator::create(desc, direct_newton(1e-6));
  EXPECT_TRUE(sim) << sim.error().message;
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                                     {.thickness = kThickness, .self_contact = false},
                                     {.meshes = {tilted_plane(t)}, .ground_height = {}});
  EXPECT_TRUE(contact) << contact.error().message;
  EXPECT_TRUE(sim->add_energy_term(*contact));
  std::shared_ptr<FrictionTerm> friction;
  if (mu) {
    auto term = FrictionTerm::create(*contact, {.obstacles = {*mu},
                                                .ground = *mu,
                                                .self = *mu,
                                                .smoothing_velocity = 1e-3,
                                                .max_passes = passes});
    EXPECT_TRUE(term) << term.error().message;
    friction = *term;
    EXPECT_TRUE(sim->add_energy_term(friction));
  }
  return {std::move(*sim), *contact, friction};
}

// The mass-weighted mean velocity of the cloth.
Vec3 mean_velocity(const ClothSimulator& sim) {
  Vec3 sum = Vec3::Zero();
  double mass = 0.0;
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    sum += sim.model().mass[i] * sim.state().velocity(i);
    mass += sim.model().mass[i];
  }
  return sum / mass;
}

Vec3 mean_position(const ClothSimulator& sim) {
  Vec3 sum = Vec3::Zero();
  double mass = 0.0;
  for (int i = 0; i < sim.model().particle_count(); ++i) {
    sum += sim.model().mass[i] * sim.state().position(i);
    mass += sim.model().mass[i];
  }
  return sum / mass;
}

// Acceleration down the slope (m/s^2), measured between steps 20 and 60 (after the patch has
// settled into the barrier) at dt = 1/60 s.
double slope_acceleration(SlopeRun& run, double t, int* friction_iterations = nullptr) {
  constexpr double dt = 1.0 / 60.0;
  double v20 = 0.0;
  for (int step = 1; step <= 60; ++step) {
    const auto report = run.sim.step(dt);
    EXPECT_TRUE(report) << report.error().message;
    if (!report) return std::numeric_limits<double>::quiet_NaN();
    EXPECT_TRUE(report->converged) << "step " << step;
    if (friction_iterations) *friction_iterations += report->friction_iterations;
    if (step == 20) v20 = -mean_velocity(run.sim).dot(slope_axis(t));
  }
  const double v60 = -mean_velocity(run.sim).dot(slope_axis(t));
  return (v60 - v20) / (40 * dt);
}

TEST(Friction, APatchOnASlopeBelowTheFrictionAngleStaysPut) {
  // mu = 0.3: the friction angle is atan(0.3) = 16.7 degrees.
  for (const double degrees : {5.0, 10.0, 15.0}) {
    const double t = radians(degrees);
    SlopeRun run = slope_run(patch_on_slope(t), t, 0.3);
    const Vec3 start = mean_position(run.sim);
    for (int step = 0; step < 60; ++step) ASSERT_TRUE(run.sim.step(1.0 / 60.0));
    // Sticking is creeping slower than the smoothing velocity eps_v = 1 mm/s (IPC's f1 < 1).
    EXPECT_LT(mean_velocity(run.sim).norm(), 1e-3) << degrees << " degrees";
    EXPECT_LT((mean_position(run.sim) - start).norm(), 1e-3) << degrees << " degrees";
    EXPECT_GT(run.friction->stats().point_triangle_pairs, 0);
  }
  // Without friction the same patch slides away at g sin t.
  const double t = radians(10.0);
  SlopeRun free = slope_run(patch_on_slope(t), t, std::nullopt);
  EXPECT_NEAR(slope_acceleration(free, t), kGravity * std::sin(t), 0.02 * kGravity * std::sin(t));
}

TEST(Friction, APatchOnASlopeAboveTheFrictionAngleSlidesAtCoulombsAcceleration) {
  const double mu = 0.3;
  for (const double degrees : {20.0, 30.0, 45.0}) {
    const double t = radians(degrees);
    SlopeRun run = slope_run(patch_on_slope(t), t, mu);
    const double expected = kGravity * (std::sin(t) - mu * std::cos(t));
    EXPECT_NEAR(slope_acceleration(run, t), expected, 0.02 * expected) << degrees << " degrees";
  }
}

TEST(Friction, RelaggingPassesKeepCoulombsAccelerationAndAreReported) {
  const double mu = 0.3, t = radians(30.0);
  SlopeRun run = slope_run(patch_on_slope(t), t, mu, 4);
  int friction_iterations = 0;
  const double expected = kGravity * (std::sin(t) - mu * std::cos(t));
  EXPECT_NEAR(slope_acceleration(run, t, &friction_iterations), expected, 0.02 * expected);
  EXPECT_GE(friction_iterations, 60);      // one pass per step at least
  EXPECT_LE(friction_iterations, 4 * 60);  // never more than the passes allowed
}

TEST(Friction, ASheetSlidingOnTheGroundStopsInVSquaredOverTwoMuG) {
  // The lab's cloth (equal masses, so every particle starts at the barrier's rest height),
  // 0.2 m, sliding at 2 m/s along x on the ground with mu = 0.5. At h = 1/240 s implicit Euler
  // falls short of v^2 / (2 mu g) by h v / 2 = 0.4 mm (0.1%).
  GridClothOptions grid{.cells = 4, .size = 0.2, .gravity = kGravity};
  grid.height = 0.5 * kThickness;
  ClothDesc desc = make_grid_cloth(grid);
  const double v0 = 2.0, mu = 0.5;
  for (ParticleDesc& p : desc.particles) {
    p.velocity = Vec3(v0, 0.0, 0.0);
    p.pinned = false;
  }
  auto sim = ClothSimulator::create(desc, direct_newton(1e-6));
  ASSERT_TRUE(sim);
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                                     {.thickness = kThickness, .self_contact = false},
                                     {.meshes = {}, .ground_height = 0.0});
  ASSERT_TRUE(contact);
  auto friction = FrictionTerm::create(*contact, {.obstacles = {}, .ground = mu});
  ASSERT_TRUE(friction) << friction.error().message;
  ASSERT_TRUE(sim->add_energy_term(*contact));
  ASSERT_TRUE(sim->add_energy_term(*friction));
  const double start = mean_position(*sim).x();
  int steps = 0;
  while (mean_velocity(*sim).x() > 1e-3 && steps < 400) {
    ASSERT_TRUE(sim->step(1.0 / 240.0));
    ++steps;
  }
  EXPECT_GT((*friction)->stats().ground_pairs, 0);
  const double expected = v0 * v0 / (2.0 * mu * kGravity);
  EXPECT_NEAR(mean_position(*sim).x() - start, expected, 0.02 * expected) << steps << " steps";
}

TEST(Friction, ZeroFrictionChangesNoBitAndPinsHold) {
  const double t = radians(30.0);
  ClothDesc desc = patch_on_slope(t);
  SlopeRun without = slope_run(desc, t, std::nullopt);
  SlopeRun zero = slope_run(desc, t, 0.0);
  for (int step = 0; step < 20; ++step) {
    ASSERT_TRUE(without.sim.step(1.0 / 60.0));
    ASSERT_TRUE(zero.sim.step(1.0 / 60.0));
  }
  EXPECT_TRUE(without.sim.state().positions == zero.sim.state().positions);
  EXPECT_TRUE(without.sim.state().velocities == zero.sim.state().velocities);

  // A corner pinned on the slope: friction pulls on its neighbours, never on it.
  desc.particles[0].pinned = true;
  const Vec3 pinned = desc.particles[0].position;
  SlopeRun held = slope_run(desc, t, 0.3, 3);
  for (int step = 0; step < 30; ++step) ASSERT_TRUE(held.sim.step(1.0 / 60.0));
  EXPECT_EQ(held.sim.state().position(0), pinned);
  EXPECT_EQ(held.sim.state().velocity(0), Vec3::Zero());
}

// A cotton sheet just above a ball and the ground, as in contact_test: pairs of every kind.
struct DerivativeSetup {
  ClothSimulator sim;
  std::shared_ptr<ContactTerm> contact;
  std::shared_ptr<FrictionTerm> friction;
};

DerivativeSetup derivative_setup() {
  GridClothOptions grid{.cells = 4, .size = 0.6, .gravity = kGravity};
  grid.height = 0.0012;
  grid.material = ClothMaterial{};
  ClothDesc desc = make_grid_cloth(grid);
  for (ParticleDesc& p : desc.particles) {
    p.position.x() -= 0.3;
    p.pinned = false;
  }
  auto sim = ClothSimulator::create(desc, {});
  EXPECT_TRUE(sim);
  TriangleMesh ball = collider_surface(SphereShape{0.3}, 3);
  for (Vec3& v : ball.vertices) v += Vec3(0.0, -0.2985, 0.0);
  auto contact =
      ContactTerm::create(std::make_shared<const ClothModel>(sim->model()),
                          {.thickness = kThickness}, {.meshes = {ball}, .ground_height = 0.0});
  EXPECT_TRUE(contact);
  auto friction = FrictionTerm::create(*contact, {.obstacles = {0.5}, .ground = 0.4, .self = 0.3});
  EXPECT_TRUE(friction);
  (*contact)->prepare(sim->state(), 1.0 / 60.0);
  (*friction)->prepare(sim->state(), 1.0 / 60.0);
  return {std::move(*sim), *contact, *friction};
}

// Displacements from x_n on both sides of eps_v h = 1.7e-5 m: particles alternately creep
// (|u| ~ 5e-6 m, the smoothed branch) and slide (|u| ~ 3e-4 m, the Coulomb branch).
Eigen::VectorXd displaced(const Eigen::VectorXd& x_start) {
  Eigen::VectorXd x = x_start;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const double size = (k / 3) % 2 == 0 ? 5e-6 : 3e-4;
    x[k] += size * std::sin(1.9 * static_cast<double>(k) + 0.3);
  }
  return x;
}

TEST(Friction, GradientMatchesFiniteDifferences) {
  DerivativeSetup s = derivative_setup();
  const FrictionStats stats = s.friction->stats();
  EXPECT_GT(stats.point_triangle_pairs, 0);
  EXPECT_GT(stats.ground_pairs, 0);
  EXPECT_GT(stats.edge_edge_pairs, 0);
  EXPECT_GT(stats.normal_force_sum, 0.0);
  const Eigen::VectorXd x = displaced(s.sim.state().positions);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero(x.size());
  s.friction->add_gradient(x, gradient);
  ASSERT_GT(gradient.norm(), 0.0);
  const double eps = 1e-9;
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    Eigen::VectorXd plus = x, minus = x;
    plus[k] += eps;
    minus[k] -= eps;
    const double fd = (s.friction->value(plus) - s.friction->value(minus)) / (2 * eps);
    EXPECT_NEAR(gradient[k], fd, 1e-5 * (std::abs(fd) + 1e-2 * gradient.norm())) << k;
    // The line search's difference agrees with two values (on a small step, where both hold).
    Eigen::VectorXd step = Eigen::VectorXd::Zero(x.size());
    step[k] = 1e-7;
    plus = x + step;
    EXPECT_NEAR(s.friction->difference(x, step), s.friction->value(plus) - s.friction->value(x),
                1e-3 * std::abs(gradient[k]) * 1e-7 + 1e-20);
  }
}

TEST(Friction, HessianMatchesFiniteDifferencesOfTheGradientAndIsPsd) {
  DerivativeSetup s = derivative_setup();
  const Eigen::VectorXd x = displaced(s.sim.state().positions);
  const Eigen::Index dofs = x.size();
  std::vector<HessianBlock> blocks;
  s.friction->add_hessian(x, true, blocks);
  ASSERT_FALSE(blocks.empty());
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero(dofs, dofs);
  for (const HessianBlock& b : blocks) {
    hessian.block<3, 3>(3 * b.row, 3 * b.col) += b.value;
    if (b.row != b.col) hessian.block<3, 3>(3 * b.col, 3 * b.row) += b.value.transpose();
  }
  const double eps = 1e-10;
  for (Eigen::Index k = 0; k < dofs; ++k) {
    Eigen::VectorXd plus = x, minus = x;
    plus[k] += eps;
    minus[k] -= eps;
    Eigen::VectorXd g_plus = Eigen::VectorXd::Zero(dofs), g_minus = Eigen::VectorXd::Zero(dofs);
    s.friction->add_gradient(plus, g_plus);
    s.friction->add_gradient(minus, g_minus);
    const Eigen::VectorXd fd = (g_plus - g_minus) / (2 * eps);
    EXPECT_LE((hessian.col(k) - fd).norm(), 1e-5 * (fd.norm() + 1e-3 * hessian.norm())) << k;
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(hessian);
  EXPECT_GE(eigen.eigenvalues().minCoeff(), -1e-9 * eigen.eigenvalues().maxCoeff());
}

TEST(Friction, BadSettingsAreRefusedByName) {
  auto sim = ClothSimulator::create(make_grid_cloth({.cells = 3}), {});
  ASSERT_TRUE(sim);
  auto contact = ContactTerm::create(std::make_shared<const ClothModel>(sim->model()), {},
                                     {.meshes = {tilted_plane(0.1)}, .ground_height = 0.0});
  ASSERT_TRUE(contact);
  const auto refusal = [&](const FrictionSettings& settings) {
    auto term = FrictionTerm::create(*contact, settings);
    return term ? std::string("accepted") : term.error().message;
  };
  EXPECT_EQ(refusal({.obstacles = {-1.0}}),
            "friction on obstacle 0 must be between 0 and 10, got -1");
  EXPECT_EQ(refusal({.obstacles = {0.3}, .ground = std::numeric_limits<double>::quiet_NaN()}),
            "friction on the ground must be between 0 and 10, got nan");
  EXPECT_EQ(refusal({.obstacles = {0.3}, .self = -0.5}),
            "friction in self-contact must be between 0 and 10, got -0.5");
  EXPECT_EQ(refusal({.obstacles = {0.3}, .smoothing_velocity = 0.0}),
            "friction smoothing velocity must be > 0 m/s, got 0");
  EXPECT_EQ(refusal({.obstacles = {0.3}, .max_passes = 0}),
            "friction passes must be at least 1, got 0");
  EXPECT_EQ(refusal({.obstacles = {}}),
            "friction lists 0 obstacle coefficients for 1 obstacle meshes");
  EXPECT_EQ(FrictionTerm::create(nullptr, {}).error().message, "friction needs a contact term");
}

}  // namespace
}  // namespace animkit
