#include "animkit/cloth/implicit_euler.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "../support/crumpled_cloth.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/material.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kFrame;

// Newton settings with the given linear solver.
NewtonSettings newton(LinearSolverKind solver, NewtonSettings settings = {}) {
  settings.linear_solver = solver;
  return settings;
}

ClothSimulator simulator(const ClothDesc& desc, const IntegratorSettings& settings,
                         int substeps = 0) {
  auto sim = ClothSimulator::create(desc, {settings, substeps});
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

// A stiff cloth crumpled at random (see crumpled_cloth.h).
ClothDesc crumpled_cloth(double stiffness) {
  return testing_support::crumpled(make_grid_cloth({.cells = 6, .stiffness = stiffness}));
}

class ImplicitIntegrators : public testing::TestWithParam<LinearSolverKind> {};

TEST_P(ImplicitIntegrators, EveryAcceptedStepSatisfiesArmijo) {
  NewtonSettings options;
  options.record_iterations = true;
  // A crumpled stiff cloth and big steps make the line search work.
  auto sim = simulator(crumpled_cloth(1e4), newton(GetParam(), options));
  int backtracked = 0;
  for (int frame = 0; frame < 30; ++frame) {
    const auto report = sim.step(1.0);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged);
    for (const IterationRecord& it : report->iterations) {
      EXPECT_LT(it.slope, 0.0);  // a descent direction
      // Armijo, checked with g evaluated on its own at both points (not the line search's
      // difference), allowing g's own rounding.
      EXPECT_LE(it.objective_after - it.objective,
                options.gamma * it.alpha * it.slope + 1e-12 * std::abs(it.objective));
      EXPECT_NEAR(it.decrease, it.objective_after - it.objective,
                  1e-9 * std::abs(it.decrease) + 1e-12 * std::abs(it.objective));
      EXPECT_GT(it.alpha, 0.0);
      // Longer than the Newton step only by doubling a projected one (see ImplicitEuler).
      if (it.alpha > 1.0) {
        EXPECT_TRUE(it.projected);
        EXPECT_EQ(std::exp2(std::round(std::log2(it.alpha))), it.alpha);
      }
      backtracked += it.line_search_steps;
    }
  }
  EXPECT_GT(backtracked, 0) << "the scene never exercised the backtracking";
}

TEST_P(ImplicitIntegrators, ExtendsProjectedStepsWhereTheClothBuckles) {
  // A cotton sheet falling from two corners folds between them within the first 15 frames:
  // the exact Hessian is indefinite there, the projected one too stiff across the compressed
  // springs.
  GridClothOptions grid{.cells = 20, .size = 1.0, .gravity = 9.81};
  grid.material = find_material("cotton")->material;
  const ClothDesc desc = make_grid_cloth(grid);
  NewtonSettings options;
  options.record_iterations = true;
  options.tolerance = 1e-6;
  auto sim = simulator(desc, newton(GetParam(), options));
  int extended = 0;
  for (int frame = 0; frame < 15; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report) << report.error().message;
    EXPECT_TRUE(report->converged) << "frame " << frame;
    for (const IterationRecord& it : report->iterations) {
      EXPECT_LT(it.objective_after, it.objective);
      if (it.alpha > 1.0) ++extended;
    }
  }
  EXPECT_GT(extended, 0) << "no projected step was extended";
}

TEST_P(ImplicitIntegrators, ConvergeToTheGradientTolerance) {
  auto sim = simulator(make_grid_cloth(), newton(GetParam()));
  for (int frame = 0; frame < 60; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_TRUE(report->converged);
    EXPECT_LE(report->gradient_norm_end, report->gradient_tolerance);
    // The tolerance is 1e-6 of the start, unless that is below rounding (first frames:
    // the flat cloth starts almost in balance).
    EXPECT_LE(report->gradient_tolerance, std::max(1e-6 * report->gradient_norm_start, 1e-9));
  }
}

TEST_P(ImplicitIntegrators, PinnedParticlesNeverMove) {
  auto sim = simulator(make_grid_cloth(), newton(GetParam()));
  const Vec3 a = sim.state().position(grid_index(10, 0, 0));
  const Vec3 b = sim.state().position(grid_index(10, 0, 10));
  for (int frame = 0; frame < 120; ++frame) {
    ASSERT_TRUE(sim.step(kFrame));
    ASSERT_EQ(sim.state().position(grid_index(10, 0, 0)), a);
    ASSERT_EQ(sim.state().position(grid_index(10, 0, 10)), b);
    ASSERT_EQ(sim.state().velocity(grid_index(10, 0, 0)), Vec3::Zero());
  }
}

TEST_P(ImplicitIntegrators, AFreeParticleFallsExactlyUnderGravity) {
  // No springs: implicit Euler is v_{n+1} = v_n - h g, x_{n+1} = x_n + h v_{n+1}, exactly.
  ClothDesc desc;
  desc.particles = {{Vec3(0.0, 10.0, 0.0), Vec3(0.5, 1.0, 0.0), 2.0, false}};
  desc.gravity = 0.3;
  auto sim = simulator(desc, newton(GetParam()));
  Vec3 x(0.0, 10.0, 0.0), v(0.5, 1.0, 0.0);
  for (int n = 0; n < 100; ++n) {
    ASSERT_TRUE(sim.step(kFrame));
    v.y() -= kFrame * 0.3;
    x += kFrame * v;
    // Equal up to rounding: the integrator forms v from (x_{n+1} - x_n) / h.
    EXPECT_LT((sim.state().position(0) - x).norm(), 1e-11);
    EXPECT_LT((sim.state().velocity(0) - v).norm(), 1e-9);
  }
}

TEST_P(ImplicitIntegrators, DampingMakesTotalEnergyDecrease) {
  // The lab's cloth falling and swinging from flat, with damping: every step loses energy,
  // never gains it.
  auto sim = simulator(make_grid_cloth({.damping = 2.0}), newton(GetParam()));
  double previous = cloth_energy(sim.model(), sim.state()).total;
  for (int frame = 0; frame < 300; ++frame) {
    const auto report = sim.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_LE(report->energy, previous + 1e-9 * std::abs(previous)) << "frame " << frame;
    previous = report->energy;
  }
}

TEST_P(ImplicitIntegrators, DashpotsDampASpringOscillator) {
  // One free particle on a soft spring (k = 1, m = 1: omega = 1 rad/s), stretched by 0.5. At
  // h = 1/60 implicit Euler's own dissipation is slow (about omega^2 h / 2 = 0.8% a second),
  // so the dashpot's is what shows: c = 0.5 (damping ratio 0.25) takes the energy down by
  // e^(-2 zeta omega t) = e^-5 in 10 s, while without it most of the energy is still there.
  const auto oscillator = [](double damping) {
    ClothDesc desc;
    desc.particles = {{Vec3::Zero(), Vec3::Zero(), 1.0, true},
                      {Vec3(1.5, 0, 0), Vec3::Zero(), 1.0, false}};
    desc.springs = {{0, 1, 1.0, 1.0}};
    desc.gravity = 0.0;
    desc.damping = damping;
    return desc;
  };
  auto damped = simulator(oscillator(0.5), newton(GetParam()));
  auto undamped = simulator(oscillator(0.0), newton(GetParam()));
  const double start = cloth_energy(damped.model(), damped.state()).total;
  ASSERT_NEAR(start, 0.125, 1e-12);
  for (int frame = 0; frame < 600; ++frame) {
    ASSERT_TRUE(damped.step(kFrame));
    ASSERT_TRUE(undamped.step(kFrame));
  }
  EXPECT_LT(cloth_energy(damped.model(), damped.state()).total, 0.02 * start);
  EXPECT_GT(cloth_energy(undamped.model(), undamped.state()).total, 0.8 * start);
}

TEST_P(ImplicitIntegrators, StableWhereExplicitEulerDiverges) {
  const ClothDesc stiff = make_grid_cloth({.stiffness = 1e4});
  auto implicit = simulator(stiff, newton(GetParam()));
  for (int frame = 0; frame < 600; ++frame) {
    const auto report = implicit.step(1.0 / 30.0);
    ASSERT_TRUE(report) << report.error().message;
  }
  // Bounded: no particle farther from the pins than the cloth's diagonal allows, nothing fast.
  for (int p = 0; p < implicit.model().particle_count(); ++p) {
    EXPECT_LT((implicit.state().position(p) - Vec3(0.0, 1.5, 0.0)).norm(), 3.5);
    EXPECT_LT(implicit.state().velocity(p).norm(), 10.0);
  }

  auto explicit_euler = simulator(stiff, ExplicitEulerSettings{}, /*substeps=*/1);
  std::optional<std::string> error;
  int frame = 0;
  for (; frame < 600 && !error; ++frame) {
    const ClothState before = explicit_euler.state();
    const auto report = explicit_euler.step(1.0 / 30.0);
    if (!report) {
      error = report.error().message;
      // The diverged step was undone: the state is the last good one.
      EXPECT_EQ(explicit_euler.state().positions, before.positions);
    }
  }
  ASSERT_TRUE(error) << "explicit Euler with one substep should diverge at stiffness 1e4";
  EXPECT_EQ(error->rfind("the simulation diverged in step " + std::to_string(frame), 0), 0u)
      << *error;
}

TEST_P(ImplicitIntegrators, TheLabsClothHangsSymmetrically) {
  // Pinned at (0,0) and (0,n), the cloth is mirror-symmetric about z = 0 and stays so while
  // it swings (a 2-unit pendulum under g = 0.3 swings for a long time: its period is ~16 s).
  // Solved tightly, so that what is checked is the method's symmetry, not how far from the
  // solution each step's stopping test lets it end (that error adds up over 600 steps; a
  // multigrid hierarchy's aggregates are not themselves symmetric).
  NewtonSettings tight;
  tight.tolerance = 1e-9;
  auto sim = simulator(make_grid_cloth(), newton(GetParam(), tight));
  const int n = 10;
  const auto expect_symmetric = [&](double tolerance) {
    for (int i = 0; i <= n; ++i) {
      for (int j = 0; j <= n; ++j) {
        const Vec3 p = sim.state().position(grid_index(n, i, j));
        const Vec3 q = sim.state().position(grid_index(n, i, n - j));
        EXPECT_NEAR(p.x(), q.x(), tolerance);
        EXPECT_NEAR(p.y(), q.y(), tolerance);
        EXPECT_NEAR(p.z(), -q.z(), tolerance);
      }
    }
  };
  for (int frame = 0; frame < 600; ++frame) ASSERT_TRUE(sim.step(kFrame));
  expect_symmetric(1e-6);
  // Steps of 2 s: implicit Euler stays stable and its numerical damping (~ omega^2 h / 2 per
  // second) stops the swing, so it settles to the rest shape: at rest, still symmetric, the
  // free edge hanging below the pins.
  for (int step = 0; step < 60; ++step) ASSERT_TRUE(sim.step(2.0));
  expect_symmetric(1e-6);
  EXPECT_LT(sim.state().position(grid_index(n, n, n / 2)).y(), -0.5);
  EXPECT_LT(sim.state().velocities.cwiseAbs().maxCoeff(), 1e-4);
  const Vec3 top = sim.state().position(grid_index(n, 0, n / 2));
  EXPECT_NEAR(top.z(), 0.0, 1e-9);
  EXPECT_LT(top.y(), 1.5);  // the edge between the pins sags
}

INSTANTIATE_TEST_SUITE_P(BothLinearSolvers, ImplicitIntegrators,
                         testing::Values(LinearSolverKind::direct, LinearSolverKind::pcg,
                                         LinearSolverKind::multigrid),
                         [](const auto& param_info) {
                           std::string name(integrator_entry(newton(param_info.param)).name);
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(ImplicitEuler, NewtonConvergesQuadraticallyNearTheSolution) {
  // Exact linear solves (direct) on a stiff cloth with big steps, where Newton needs several
  // iterations. Near the solution each full Newton step about squares the relative gradient
  // norm: e_{k+1} <= C e_k^2. A linearly convergent method at rate r has e_{k+1} / e_k^2 =
  // r / e_k: the always-projected Hessian (r ~ 0.2-0.3) breaks C = 2000 once e_k < 1e-4.
  NewtonSettings options;
  options.record_iterations = true;
  options.tolerance = 1e-12;
  auto sim = simulator(make_grid_cloth({.cells = 6, .stiffness = 1e4}),
                       newton(LinearSolverKind::direct, options));
  int pairs = 0;
  for (int frame = 0; frame < 12; ++frame) {
    const auto report = sim.step(0.2);
    ASSERT_TRUE(report);
    ASSERT_TRUE(report->converged);
    const auto& its = report->iterations;
    for (std::size_t k = 0; k < its.size(); ++k) {
      const double e = its[k].gradient_norm / report->gradient_norm_start;
      const double next =
          (k + 1 < its.size() ? its[k + 1].gradient_norm : report->gradient_norm_end) /
          report->gradient_norm_start;
      // Full, exact-Hessian steps from close to the solution, landing above rounding.
      if (e > 1e-3 || next < 1e-11 || its[k].projected || its[k].alpha < 1.0) continue;
      EXPECT_LE(next, 2000.0 * e * e) << "frame " << frame << ": " << e << " -> " << next;
      ++pairs;
    }
  }
  EXPECT_GE(pairs, 8) << "too few iterates close to the solution to judge";
}

TEST(ImplicitEuler, AlwaysProjectingConvergesButMoreSlowly) {
  // The projected Hessian is a safe but inexact model where springs are compressed.
  NewtonSettings exact, projected;
  projected.projection = HessianProjection::always;
  auto a = simulator(make_grid_cloth({.cells = 6, .stiffness = 1e4}),
                     newton(LinearSolverKind::direct, exact));
  auto b = simulator(make_grid_cloth({.cells = 6, .stiffness = 1e4}),
                     newton(LinearSolverKind::direct, projected));
  int newton_exact = 0, newton_projected = 0;
  for (int frame = 0; frame < 12; ++frame) {
    const auto ra = a.step(0.2), rb = b.step(0.2);
    ASSERT_TRUE(ra && rb);
    EXPECT_TRUE(ra->converged && rb->converged);
    newton_exact += ra->newton_iterations;
    newton_projected += rb->newton_iterations;
    EXPECT_EQ(rb->projected_iterations, rb->newton_iterations);
    // Same minimizer, to the tolerance: compare after the first step, before the buckling
    // cloth amplifies the tolerance-sized differences.
    if (frame == 0) {
      EXPECT_LT((a.state().positions - b.state().positions).cwiseAbs().maxCoeff(), 1e-6);
    }
  }
  EXPECT_LT(newton_exact, newton_projected);
}

TEST(ImplicitEuler, DirectAndPcgReachTheSameState) {
  auto direct = simulator(make_grid_cloth(), newton(LinearSolverKind::direct));
  auto pcg = simulator(make_grid_cloth(), newton(LinearSolverKind::pcg));
  for (int frame = 0; frame < 120; ++frame) {
    ASSERT_TRUE(direct.step(kFrame));
    ASSERT_TRUE(pcg.step(kFrame));
  }
  EXPECT_LT((direct.state().positions - pcg.state().positions).cwiseAbs().maxCoeff(), 1e-6);
}

TEST(ClothSimulator, RejectsBadInput) {
  auto sim = simulator(make_grid_cloth(), newton(LinearSolverKind::pcg));
  EXPECT_EQ(sim.step(0.0).error().message, "time step must be between 1e-06 and 10, got 0");
  EXPECT_EQ(sim.step(std::nan("")).error().message,
            "time step must be between 1e-06 and 10, got nan");
  NewtonSettings bad;
  bad.tolerance = 0.0;
  EXPECT_EQ(ClothSimulator::create(make_grid_cloth(), {bad, 0}).error().message,
            "tolerance must be in (0, 1), got 0");
  EXPECT_EQ(
      ClothSimulator::create(make_grid_cloth(), {ExplicitEulerSettings{}, -1}).error().message,
      "substeps must be between 1 and 100000 (or 0 for the default), got -1");
}

TEST(ClothSimulator, SetStateRestartsFromASavedState) {
  auto sim = simulator(make_grid_cloth({.cells = 4}), newton(LinearSolverKind::pcg));
  for (int frame = 0; frame < 10; ++frame) ASSERT_TRUE(sim.step(kFrame));
  const ClothState saved = sim.state();
  ASSERT_TRUE(sim.step(kFrame));
  const ClothState next = sim.state();
  ASSERT_TRUE(sim.set_state(saved));
  ASSERT_TRUE(sim.step(kFrame));
  EXPECT_EQ(sim.state().positions, next.positions);  // deterministic: same bits again
  ClothState bad = saved;
  bad.positions[7] = std::nan("");
  EXPECT_EQ(sim.set_state(bad).error().message, "state has a non-finite position or velocity");
  bad.positions.resize(9);
  EXPECT_EQ(sim.set_state(bad).error().message, "state has 3 particles but the cloth has 25");
}

TEST(ClothSimulator, ExplicitEulerWithTheLabsSubstepsIsStableAndAgreesWithImplicit) {
  auto explicit_euler = simulator(make_grid_cloth(), ExplicitEulerSettings{});
  auto implicit = simulator(make_grid_cloth(), newton(LinearSolverKind::pcg));
  for (int frame = 0; frame < 60; ++frame) {
    const auto report = explicit_euler.step(kFrame);
    ASSERT_TRUE(report);
    EXPECT_EQ(report->substeps, 1000);
    ASSERT_TRUE(implicit.step(kFrame));
  }
  // First-order methods on the same motion: close, not equal (implicit Euler damps).
  EXPECT_LT((explicit_euler.state().positions - implicit.state().positions).cwiseAbs().maxCoeff(),
            0.05);
}

}  // namespace
}  // namespace animkit

namespace animkit {
namespace {

// A constant external force on a lone particle gives exact uniform acceleration under both
// integrators (implicit Euler: x_{n+1} = x_n + h v_n + h^2 a), as gravity does.
TEST(ClothSimulator, ExternalForcesAccelerateLikeGravity) {
  ClothDesc desc;
  desc.particles = {{Vec3::Zero(), Vec3::Zero(), 2.0, false},
                    {Vec3(1, 0, 0), Vec3::Zero(), 1.0, true}};
  desc.gravity = 0.0;
  for (const IntegratorEntry& entry : cloth_integrators()) {
    auto sim = ClothSimulator::create(desc, {entry.defaults, 1});
    ASSERT_TRUE(sim.has_value()) << sim.error().message;
    Eigen::VectorXd forces = Eigen::VectorXd::Zero(6);
    forces.segment<3>(0) = Vec3(4.0, 0.0, -2.0);  // a = (2, 0, -1)
    forces.segment<3>(3) = Vec3(9.0, 9.0, 9.0);   // on the pinned particle: no effect
    ASSERT_TRUE(sim->set_external_forces(forces).has_value());
    const double h = 0.1;
    for (int n = 0; n < 10; ++n) ASSERT_TRUE(sim->step(h).has_value());
    // Velocity after 10 steps is 10 h a; position sums h v_k for k = 1..10: h^2 a 55.
    EXPECT_NEAR(sim->state().velocity(0).x(), 10 * h * 2.0, 1e-9);
    EXPECT_NEAR(sim->state().position(0).x(), 55 * h * h * 2.0, 1e-9);
    EXPECT_NEAR(sim->state().position(0).z(), -55 * h * h * 1.0, 1e-9);
    EXPECT_EQ(sim->state().position(1), Vec3(1, 0, 0));
    sim->clear_external_forces();
    const Vec3 v = sim->state().velocity(0);
    ASSERT_TRUE(sim->step(h).has_value());
    EXPECT_NEAR((sim->state().velocity(0) - v).norm(), 0.0, 1e-9);
  }
}

TEST(ClothSimulator, RejectsBadExternalForces) {
  auto sim = ClothSimulator::create(make_grid_cloth({.cells = 2}), {});
  ASSERT_TRUE(sim.has_value());
  const auto short_forces = sim->set_external_forces(Eigen::VectorXd::Zero(5));
  ASSERT_FALSE(short_forces.has_value());
  EXPECT_EQ(short_forces.error().message, "external forces have 5 entries but the cloth needs 27");
  Eigen::VectorXd nan = Eigen::VectorXd::Zero(27);
  nan[4] = std::numeric_limits<double>::infinity();
  const auto bad = sim->set_external_forces(nan);
  ASSERT_FALSE(bad.has_value());
  EXPECT_EQ(bad.error().message, "external forces have a non-finite value");
}

}  // namespace
}  // namespace animkit
