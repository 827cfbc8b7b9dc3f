#include "animkit/cloth/block_jacobi_pcg.h"
#include "animkit/cloth/multigrid_pcg.h"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/hessian_pattern.h"
#include "animkit/cloth/incremental_potential.h"

namespace animkit {
namespace {

constexpr double kFrame = 1.0 / 60.0;

// The Newton system at the start of a step of a hanging cloth: the cotton scene's parameters
// (per-particle mass 0.15 kg spread over the grid) on a smaller grid, after `frames` steps.
struct NewtonSystem {
  ClothModel model;
  BlockHessian a;
  Eigen::VectorXd b;
};

NewtonSystem hanging_system(const ClothDesc& desc, int frames) {
  auto sim = ClothSimulator::create(desc, {});
  EXPECT_TRUE(sim) << sim.error().message;
  for (int f = 0; f < frames; ++f) EXPECT_TRUE(sim->step(kFrame));
  NewtonSystem system{sim->model(), BlockHessian(sim->model()), {}};
  IncrementalPotential potential(system.model);
  potential.prepare(sim->state(), kFrame);
  potential.hessian(potential.predicted(), system.a, /*projected=*/true);
  system.b.resize(3 * system.model.particle_count());
  potential.gradient(potential.predicted(), system.b);
  system.b = -system.b;
  return system;
}

ClothDesc cotton(int cells, double stiffness) {
  const double particles = (cells + 1.0) * (cells + 1.0);
  return make_grid_cloth({.cells = cells,
                          .size = 1.0,
                          .height = 1.5,
                          .mass = 0.15 / particles,
                          .stiffness = stiffness,
                          .damping = 0.0,
                          .gravity = 9.81});
}

// A grid with every third spring removed and the particles renumbered at random: an irregular
// graph in no particular order, as a triangle mesh would give.
ClothDesc irregular_cloth() {
  const ClothDesc grid = cotton(12, 1000.0);
  std::vector<int> order(grid.particles.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  std::mt19937 rng(7);
  std::shuffle(order.begin(), order.end(), rng);
  ClothDesc desc = grid;
  for (std::size_t i = 0; i < order.size(); ++i) desc.particles[order[i]] = grid.particles[i];
  desc.springs.clear();
  for (std::size_t s = 0; s < grid.springs.size(); ++s) {
    if (s % 3 == 2) continue;
    SpringDesc spring = grid.springs[s];
    spring.a = order[spring.a];
    spring.b = order[spring.b];
    desc.springs.push_back(spring);
  }
  desc.triangles.clear();
  return desc;
}

Eigen::VectorXd direct_solve(const NewtonSystem& system) {
  HessianPattern pattern = build_hessian_pattern(system.model);
  pattern.assign(system.a);
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(pattern.matrix);
  EXPECT_EQ(ldlt.info(), Eigen::Success);
  return ldlt.solve(system.b);
}

void expect_matches_direct_solve(const NewtonSystem& system) {
  MultigridPcg pcg(system.model);
  EXPECT_GT(pcg.level_count(), 1);
  Eigen::VectorXd x(system.b.size());
  const PcgResult result = pcg.solve(system.a, system.b, x, 1e-8, 200);
  EXPECT_TRUE(result.converged);
  EXPECT_FALSE(result.indefinite);
  EXPECT_LE(result.relative_residual, 1e-8);
  Eigen::VectorXd ax(x.size());
  system.a.multiply(system.model, x, ax);
  EXPECT_LE((system.b - ax).norm(), 1e-8 * system.b.norm());
  const Eigen::VectorXd expected = direct_solve(system);
  EXPECT_LE((x - expected).norm(), 1e-6 * expected.norm());
  for (int i = 0; i < system.model.particle_count(); ++i) {
    if (system.model.pinned[i]) {
      EXPECT_EQ(x.segment<3>(3 * i).norm(), 0.0) << "particle " << i;
    }
  }
}

TEST(MultigridPcg, MatchesDirectSolveOnHangingGrid) {
  expect_matches_direct_solve(hanging_system(cotton(16, 1000.0), 10));
}

TEST(MultigridPcg, MatchesDirectSolveOnIrregularSpringGraph) {
  expect_matches_direct_solve(hanging_system(irregular_cloth(), 10));
}

TEST(MultigridPcg, PreconditionerIsSymmetricPositiveDefinite) {
  const NewtonSystem system = hanging_system(cotton(16, 1e4), 10);
  MultigridPcg pcg(system.model);
  Eigen::VectorXd x(system.b.size());
  (void)pcg.solve(system.a, system.b, x, 1e-2, 100);  // sets the preconditioner up
  std::mt19937 rng(11);
  std::normal_distribution<double> normal;
  const auto random_vector = [&] {
    Eigen::VectorXd v(system.b.size());
    for (Eigen::Index k = 0; k < v.size(); ++k) v[k] = normal(rng);
    // Pinned entries are not unknowns: CG's residuals are zero there.
    for (int i = 0; i < system.model.particle_count(); ++i) {
      if (system.model.pinned[i]) v.segment<3>(3 * i).setZero();
    }
    return v;
  };
  Eigen::VectorXd z1(system.b.size()), z2(system.b.size());
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd r1 = random_vector(), r2 = random_vector();
    pcg.apply_preconditioner(r1, z1);
    pcg.apply_preconditioner(r2, z2);
    EXPECT_GT(r1.dot(z1), 0.0);
    EXPECT_GT(r2.dot(z2), 0.0);
    EXPECT_NEAR(r1.dot(z2), r2.dot(z1), 1e-10 * std::sqrt(r1.dot(z1) * r2.dot(z2)));
  }
}

TEST(MultigridPcg, SameInputSameBits) {
  const NewtonSystem system = hanging_system(cotton(16, 1000.0), 5);
  MultigridPcg first(system.model), second(system.model);
  Eigen::VectorXd x1(system.b.size()), x2(system.b.size()), x3(system.b.size());
  (void)first.solve(system.a, system.b, x1, 1e-6, 100);
  (void)second.solve(system.a, system.b, x2, 1e-6, 100);
  (void)first.solve(system.a, system.b, x3, 1e-6, 100);
  EXPECT_EQ(x1, x2);
  EXPECT_EQ(x1, x3);
}

int iterations(const ClothDesc& desc, double tolerance) {
  const NewtonSystem system = hanging_system(desc, 10);
  MultigridPcg pcg(system.model);
  Eigen::VectorXd x(system.b.size());
  const PcgResult result = pcg.solve(system.a, system.b, x, tolerance, 500);
  EXPECT_TRUE(result.converged);
  return result.iterations;
}

// Multigrid's point: the iteration count hardly depends on the resolution or the stiffness
// (block Jacobi's grows like sqrt(k h^2 / m) times the resolution).
TEST(MultigridPcg, IterationsBoundedUnderRefinementAndStiffness) {
  const int base = iterations(cotton(16, 1000.0), 1e-6);
  const int finer = iterations(cotton(32, 1000.0), 1e-6);      // 4x the particles
  const int stiffer = iterations(cotton(16, 100000.0), 1e-6);  // 100x the stiffness
  EXPECT_LE(finer, 1.5 * base + 1) << base << " -> " << finer;
  EXPECT_LE(stiffer, 1.5 * base + 1) << base << " -> " << stiffer;
  EXPECT_LE(base, 20);

  const NewtonSystem system = hanging_system(cotton(32, 1000.0), 10);
  BlockJacobiPcg jacobi(system.model);
  Eigen::VectorXd x(system.b.size());
  const PcgResult reference = jacobi.solve(system.a, system.b, x, 1e-6, 5000);
  EXPECT_GT(reference.iterations, 4 * finer);
}

TEST(MultigridPcg, ZeroRightHandSideGivesZero) {
  const NewtonSystem system = hanging_system(cotton(8, 1000.0), 1);
  MultigridPcg pcg(system.model);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(system.b.size());
  const PcgResult result = pcg.solve(system.a, Eigen::VectorXd::Zero(system.b.size()), x, 1e-6, 10);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_EQ(x.norm(), 0.0);
}

}  // namespace
}  // namespace animkit
