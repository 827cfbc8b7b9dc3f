// NewtonSettings::velocity_tolerance: IPC's stopping test |dx|_inf / h <= tolerance * L.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "../support/crumpled_cloth.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/contact.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/implicit_substep.h"

namespace animkit {
namespace {

ClothSimulator newton_simulator(const ClothDesc& desc, const NewtonSettings& settings) {
  auto sim = ClothSimulator::create(desc, {settings, 0});
  EXPECT_TRUE(sim) << sim.error().message;
  return std::move(*sim);
}

// A stiff cloth crumpled at random, stepped with h = 0.2: Newton needs several iterations.
ClothDesc crumpled_stiff_cloth() {
  return testing_support::crumpled(make_grid_cloth({.cells = 6, .stiffness = 1e4}));
}

// The velocity tolerance and CG's fixed forcing term both take [0, 1).
TEST(VelocityStop, RejectsToleranceAndLinearForcingOutsideZeroToOne) {
  for (const auto& [setting, message] :
       {std::pair{&NewtonSettings::velocity_tolerance,
                  "velocity tolerance must be in [0, 1), got "},
        std::pair{&NewtonSettings::linear_forcing, "linear forcing must be in [0, 1), got "}}) {
    for (const double bad : {-1e-3, 1.0, std::numeric_limits<double>::quiet_NaN(),
                             std::numeric_limits<double>::infinity()}) {
      NewtonSettings settings;
      settings.*setting = bad;
      const auto sim = ClothSimulator::create(make_grid_cloth(), {settings, 0});
      ASSERT_FALSE(sim);
      EXPECT_EQ(sim.error().message.rfind(message, 0), 0u) << sim.error().message;
    }
  }
}

TEST(VelocityStop, BoundingDiagonalIsTheBoxOfThePoints) {
  Eigen::VectorXd points(9);
  points << 0, 0, 0, 3, 0, -1, 1, 4, 0;
  EXPECT_DOUBLE_EQ(bounding_diagonal(points), std::sqrt(9.0 + 16.0 + 1.0));
  EXPECT_EQ(bounding_diagonal(Eigen::VectorXd()), 0.0);
}

// The test's meaning: Newton converges quadratically near the solution, so the correction it
// would still make is about the distance left to the exact step. Each step, from the same
// state, ends within a few times tolerance * L * h of a tightly converged step. So does it with
// CG stopped at a fixed 10% residual (linear_forcing): the next correction it measures is then
// inexact, but the test still means the same.
TEST(VelocityStop, EndsWithinTheToleranceOfTheExactStep) {
  constexpr double kTolerance = 1e-3;
  constexpr double kStep = 0.2;
  for (const auto& [solver, forcing] :
       {std::pair{LinearSolverKind::direct, 0.0}, std::pair{LinearSolverKind::multigrid, 0.0},
        std::pair{LinearSolverKind::multigrid, 0.1}, std::pair{LinearSolverKind::pcg, 0.1}}) {
    NewtonSettings loose;
    loose.linear_solver = solver;
    loose.linear_forcing = forcing;
    loose.tolerance = 1e-12;  // below rounding: only the velocity test (or the floor) stops
    loose.velocity_tolerance = kTolerance;
    NewtonSettings tight;
    tight.linear_solver = LinearSolverKind::direct;
    tight.tolerance = 1e-12;
    auto sim = newton_simulator(crumpled_stiff_cloth(), loose);
    auto reference = newton_simulator(crumpled_stiff_cloth(), tight);
    int loose_iterations = 0, tight_iterations = 0;
    for (int frame = 0; frame < 12; ++frame) {
      const ClothState start = sim.state();
      const double allowed = kTolerance * bounding_diagonal(start.positions);
      ASSERT_TRUE(reference.set_state(start));
      const auto report = sim.step(kStep);
      const auto exact = reference.step(kStep);
      ASSERT_TRUE(report && exact);
      EXPECT_TRUE(report->converged) << "frame " << frame;
      // Stopped by the velocity test, or earlier by the gradient's rounding floor.
      EXPECT_TRUE(report->newton_speed_end <= allowed ||
                  report->gradient_norm_end <= report->gradient_tolerance)
          << "frame " << frame << ": " << report->newton_speed_end << " m/s";
      const double error =
          (sim.state().positions - reference.state().positions).lpNorm<Eigen::Infinity>();
      EXPECT_LE(error, 3.0 * allowed * kStep) << "frame " << frame;
      loose_iterations += report->newton_iterations;
      tight_iterations += exact->newton_iterations;
    }
    // It is a looser test than a gradient at rounding level: it must save iterations.
    EXPECT_LT(loose_iterations, tight_iterations);
  }
}

constexpr double kThickness = 2e-3;

// A 0.3 m cotton sheet `height` above the ground, with contact of kThickness, stepped by
// Newton with the multigrid preconditioner, the velocity stop at 1e-3 and CG's `forcing`.
ClothSimulator cotton_over_ground(double height, double forcing) {
  GridClothOptions grid{.cells = 6, .size = 0.3, .gravity = 9.81};
  grid.height = height;
  grid.material = ClothMaterial{};
  grid.pins = GridPins::none;
  NewtonSettings settings;
  settings.linear_solver = LinearSolverKind::multigrid;
  settings.tolerance = 1e-4;
  settings.velocity_tolerance = 1e-3;
  settings.linear_forcing = forcing;
  settings.max_iterations = 300;
  auto sim = newton_simulator(make_grid_cloth(grid), settings);
  auto contact =
      ContactTerm::create(std::make_shared<const ClothModel>(sim.model()),
                          {.thickness = kThickness}, {.meshes = {}, .ground_height = 0.0});
  EXPECT_TRUE(contact) << contact.error().message;
  if (contact) {
    EXPECT_TRUE(sim.add_energy_term(*contact));
  }
  return sim;
}

// A cotton sheet dropped 5 mm onto the ground rests on it for 90 steps, every step converged
// and no gap below a tenth of the thickness, with CG's adaptive forcing and with the fixed 10%
// of the fast settings.
TEST(VelocityStop, RestingContactConvergesAndKeepsItsGap) {
  for (const double forcing : {0.0, 0.1}) {
    ClothSimulator sim = cotton_over_ground(5e-3, forcing);
    for (int frame = 0; frame < 90; ++frame) {
      const auto report = sim.step(1.0 / 30.0);
      ASSERT_TRUE(report) << report.error().message;
      EXPECT_TRUE(report->converged) << "frame " << frame;
      if (report->contact_pairs > 0) {
        EXPECT_GE(report->min_contact_distance, 0.1 * kThickness)
            << "frame " << frame << ", forcing " << forcing;
      }
    }
  }
}

// A substep may start where a gap is squeezed (CCD's minimum separation leaves a tenth of
// it). A barrier's Newton correction at a small gap is about as small as the gap, so the
// velocity test alone would end the substep there, and the gap would shrink every step until
// rounding let the cloth through; it waits until no vertex of a close pair moves by more than
// a tenth of its gap (ContactTerm::gaps_settled). A sheet at rest 5 micrometres above the
// ground (its resting gap is about 0.8 mm) must reopen the gap within one step.
TEST(VelocityStop, SqueezedGapReopensBeforeTheStepEnds) {
  ClothSimulator sim = cotton_over_ground(5e-6, 0.0);
  const auto report = sim.step(1.0 / 30.0);
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_TRUE(report->converged);
  EXPECT_GE(report->min_contact_distance, 0.1 * kThickness);
}

// The contact's side of the test above: a gap is settled when no vertex of its pair would
// move by more than a tenth of it, however small the gap (cloth pressed under others rests
// at a hundredth of the thickness); without pairs any correction is.
TEST(VelocityStop, ContactGapsAreSettledWhenNoVertexMovesATenthOfItsGap) {
  GridClothOptions grid{.cells = 1, .size = 0.1, .gravity = 9.81};
  grid.material = ClothMaterial{};
  grid.pins = GridPins::none;
  auto sim = newton_simulator(make_grid_cloth(grid), NewtonSettings{});
  auto contact =
      ContactTerm::create(std::make_shared<const ClothModel>(sim.model()),
                          {.thickness = kThickness}, {.meshes = {}, .ground_height = 0.0});
  ASSERT_TRUE(contact) << contact.error().message;
  ContactTerm& term = **contact;
  Eigen::VectorXd x = sim.state().positions;
  Eigen::VectorXd dx = Eigen::VectorXd::Zero(x.size());
  for (const double height : {0.02e-3, 0.15e-3, 1e-3, 0.5}) {
    for (int i = 0; i < sim.model().particle_count(); ++i) x[3 * i + 1] = height;
    term.update(x);  // gathers the pairs at x
    for (const double move : {1e-6, 1e-5, 1e-4}) {
      dx[3 * 2 + 1] = -move;  // one particle down toward the ground
      EXPECT_EQ(term.gaps_settled(x, dx), move <= 0.1 * height || height >= 2e-3)
          << "height " << height << ", move " << move;
      dx[3 * 2 + 1] = 0.0;
      dx[3 * 2] = move;  // or along it: the pair's distance alone does not show that
      EXPECT_EQ(term.gaps_settled(x, dx), move <= 0.1 * height || height >= 2e-3)
          << "height " << height << ", move " << move << " sideways";
      dx[3 * 2] = 0.0;
    }
  }
}

TEST(VelocityStop, OffByDefaultButTheSpeedIsReported) {
  auto sim = newton_simulator(crumpled_stiff_cloth(), NewtonSettings{});
  const auto report = sim.step(0.2);
  ASSERT_TRUE(report);
  EXPECT_TRUE(report->converged);
  EXPECT_LE(report->gradient_norm_end, report->gradient_tolerance);
  EXPECT_GT(report->newton_speed_end, 0.0);
}

}  // namespace
}  // namespace animkit
