// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// with -march=native at -O1 (a false positive in the compiler's own headers, see
// psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "animkit/cloth/multigrid_pcg.h"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <random>

#include "animkit/cloth/block_jacobi_pcg.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/hessian_pattern.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/core/threads.h"
#include "shared_constants.h"

namespace animkit {
namespace {

using testing_support::kFrame;

// The Newton system at the start of a step of a hanging cloth: the cotton scene's parameters
// (per-particle mass 0.15 kg spread over the grid) on a smaller grid, after `frames` steps.
struct NewtonSystem {
  ClothModel model;
  BlockHessian a;
  Eigen::VectorXd b;
};

NewtonSystem hanging_system(const ClothDesc& desc, int frames) {
  // The frames before it run on the multigrid integrator: how the state was reached is not
  // what these tests check, and block-Jacobi CG took most of their time (under the sanitizers
  // IterationsBoundedUnderRefinementAndStiffness went from 50 s to 28 s).
  auto sim = ClothSimulator::create(desc, {find_integrator("implicit-multigrid")->defaults, 0});
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

void expect_matches_direct_solve(const NewtonSystem& system, const MultigridOptions& options = {}) {
  MultigridPcg pcg(system.model, options);
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

// More than one sweep takes the residual from a whole product (one sweep reuses the sweep's).
TEST(MultigridPcg, MatchesDirectSolveWithTwoSweeps) {
  expect_matches_direct_solve(hanging_system(cotton(16, 1000.0), 10), {.smoothing_sweeps = 2});
}

// The V-cycle set up for `system`'s matrix, applied to random vectors over the free particles:
// r . B r > 0 and r1 . B r2 = r2 . B r1.
void expect_symmetric_positive_definite(const NewtonSystem& system, unsigned seed,
                                        const MultigridOptions& options = {}) {
  MultigridPcg pcg(system.model, options);
  Eigen::VectorXd x(system.b.size());
  (void)pcg.solve(system.a, system.b, x, 1e-2, 100);  // sets the preconditioner up
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::VectorXd r1(system.b.size()), r2(system.b.size()), z1(r1.size()), z2(r1.size());
  for (int trial = 0; trial < 5; ++trial) {
    for (Eigen::Index k = 0; k < r1.size(); ++k) {
      // Pinned entries are not unknowns: CG's residuals are zero there.
      const bool free = !system.model.pinned[static_cast<std::size_t>(k / 3)];
      r1[k] = free ? normal(rng) : 0.0;
      r2[k] = free ? normal(rng) : 0.0;
    }
    pcg.apply_preconditioner(r1, z1);
    pcg.apply_preconditioner(r2, z2);
    EXPECT_GT(r1.dot(z1), 0.0);
    EXPECT_GT(r2.dot(z2), 0.0);
    EXPECT_NEAR(r1.dot(z2), r2.dot(z1), 1e-10 * std::sqrt(r1.dot(z1) * r2.dot(z2)));
  }
}

TEST(MultigridPcg, PreconditionerIsSymmetricPositiveDefinite) {
  expect_symmetric_positive_definite(hanging_system(cotton(16, 1e4), 10), 11);
}

// A material sheet: bends (three particles in a line) instead of the distance-2 springs. The
// bends' couplings between the line's ends stay out of the hierarchy, lumped onto the
// diagonal. With a bend as stiff as the membrane, dropping them without that leaves the
// preconditioner's matrix indefinite, and CG does not reach the direct solve's answer.
ClothDesc stiff_bending_sheet() {
  ClothMaterial material;  // cotton's membrane
  material.bending = 4.0;  // B / s^2 = 1024 N/m at 16 cells per metre: the stretch's size
  material.density = 0.01;
  return make_grid_cloth({.cells = 16, .size = 1.0, .height = 1.5, .gravity = 9.81,
                          .material = material});
}

TEST(MultigridPcg, MatchesDirectSolveWithStiffBends) {
  const NewtonSystem system = hanging_system(stiff_bending_sheet(), 10);
  ASSERT_GT(system.model.bend_count(), 0);
  expect_matches_direct_solve(system);
}

// The finest level holds a block per particle and two per spring between free particles, the
// bends' coupling springs (stiffness 0) left out.
TEST(MultigridPcg, TheFinestLevelLeavesTheBendsCouplingsOut) {
  const NewtonSystem system = hanging_system(stiff_bending_sheet(), 1);
  const ClothModel& model = system.model;
  int stiff = 0, coupling = 0;
  for (int s = 0; s < model.spring_count(); ++s) {
    const auto [a, b] = model.springs[static_cast<std::size_t>(s)];
    if (model.pinned[a] || model.pinned[b]) continue;
    (model.stiffness[static_cast<std::size_t>(s)] > 0.0 ? stiff : coupling) += 1;
  }
  ASSERT_GT(coupling, 0);
  const MultigridPcg pcg(model);
  EXPECT_EQ(pcg.level_blocks(0), model.particle_count() + 2 * stiff);
}

TEST(MultigridPcg, PreconditionerWithStiffBendsIsSymmetricPositiveDefinite) {
  expect_symmetric_positive_definite(hanging_system(stiff_bending_sheet(), 10), 17);
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

// Contact-like couplings: a stiff PSD block k n n^T pushing particle i off particle j along n,
// for pairs far apart on the grid (a cloth folded onto itself), added as an energy term adds
// them (BlockHessian::extra, diagonal blocks also in `diagonal`).
void add_far_couplings(NewtonSystem& system, int cells, double k) {
  const int side = cells + 1;
  std::mt19937 rng(5);
  std::normal_distribution<double> normal;
  for (int i = 0; i < side / 2; ++i) {
    for (int j = 0; j < side; j += 3) {
      const int a = grid_index(cells, i, j), b = grid_index(cells, cells - i, j);
      if (system.model.pinned[a] || system.model.pinned[b] || a == b) continue;
      const Eigen::Vector3d n = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
      const Eigen::Matrix3d block = k * n * n.transpose();
      system.a.diagonal[a] += block;
      system.a.diagonal[b] += block;
      system.a.extra.push_back({a, a, block});
      system.a.extra.push_back({b, b, block});
      system.a.extra.push_back({a, b, -block});
    }
  }
  system.a.renew_terms_revision();
}

Eigen::VectorXd dense_solve(const NewtonSystem& system) {
  const auto size = system.b.size();
  Eigen::MatrixXd dense(size, size);
  Eigen::VectorXd unit = Eigen::VectorXd::Zero(size), column(size);
  for (Eigen::Index c = 0; c < size; ++c) {
    unit[c] = 1.0;
    system.a.multiply(system.model, unit, column);
    dense.col(c) = column;
    unit[c] = 0.0;
  }
  return dense.llt().solve(system.b);
}

NewtonSystem coupled_system(int cells, double k) {
  NewtonSystem system = hanging_system(cotton(cells, 1000.0), 10);
  add_far_couplings(system, cells, k);
  return system;
}

TEST(MultigridPcg, MatchesDenseSolveWithFarCouplings) {
  const NewtonSystem system = coupled_system(16, 1e5);
  ASSERT_FALSE(system.a.extra.empty());
  MultigridPcg pcg(system.model);
  EXPECT_GT(pcg.level_count(), 1);
  Eigen::VectorXd x(system.b.size());
  const PcgResult result = pcg.solve(system.a, system.b, x, 1e-9, 300);
  EXPECT_TRUE(result.converged);
  const Eigen::VectorXd expected = dense_solve(system);
  EXPECT_LE((x - expected).norm(), 1e-6 * expected.norm());
}

// With a single level the V-cycle is the coarsest level's Cholesky solve: exact only if the
// couplings are part of that level's operator, and then CG needs one iteration.
TEST(MultigridPcg, CouplingsArePartOfTheOperatorOnEveryLevel) {
  const NewtonSystem system = coupled_system(8, 1e5);
  MultigridPcg pcg(system.model, {.coarsest_nodes = 1000});
  EXPECT_EQ(pcg.level_count(), 1);
  Eigen::VectorXd x(system.b.size());
  const PcgResult result = pcg.solve(system.a, system.b, x, 1e-9, 50);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 1);
}

// The same system with every spring 1.5 times as stiff: the springs' blocks change, the terms'
// blocks and their revision stay (what Newton's projected retry does).
NewtonSystem with_stiffer_springs(NewtonSystem system) {
  for (std::size_t s = 0; s < system.model.springs.size(); ++s) {
    const Eigen::Matrix3d more = 0.5 * system.a.coupling[s];
    system.a.coupling[s] += more;
    for (const int end : system.model.springs[s])
      if (!system.model.pinned[end]) system.a.diagonal[end] += more;
  }
  return system;
}

// The terms' couplings twice as stiff (still PSD), under the same revision: what a caller
// that forgot to renew it would pass.
NewtonSystem with_stiffer_couplings(NewtonSystem system) {
  for (HessianBlock& block : system.a.extra) {
    if (block.row == block.col) system.a.diagonal[block.row] += block.value;
    block.value *= 2.0;
  }
  return system;
}

// A Hessian whose terms' blocks keep their revision keeps their couplings' restrictions: the
// same bits as a hierarchy built anew. Under the same revision the first blocks stay in use
// (so whoever changes them must renew it); a new revision takes the new ones. A prolongator
// smoothed with each matrix (resmooth) restricts them anew every time.
TEST(MultigridPcg, KeepsTheCouplingsOfTheSameTermsRevision) {
  const NewtonSystem system = coupled_system(16, 1e5);
  const NewtonSystem stiffer = with_stiffer_springs(system);
  NewtonSystem changed = with_stiffer_couplings(stiffer);
  const auto size = system.b.size();
  for (const bool resmooth : {false, true}) {
    SCOPED_TRACE(resmooth ? "resmooth" : "fixed prolongators");
    const MultigridOptions options{.resmooth = resmooth};
    MultigridPcg reused(system.model, options), fresh(system.model, options),
        other(system.model, options);
    Eigen::VectorXd first(size), kept(size), expected(size);
    (void)reused.solve(system.a, system.b, first, 1e-5, 300);
    const PcgResult result = reused.solve(stiffer.a, stiffer.b, kept, 1e-5, 300);
    (void)fresh.solve(stiffer.a, stiffer.b, expected, 1e-5, 300);
    ASSERT_TRUE(result.converged);
    EXPECT_EQ(kept, expected);

    Eigen::VectorXd stale(size), renewed(size), expected_changed(size);
    changed.a.terms_revision = stiffer.a.terms_revision;
    (void)reused.solve(changed.a, changed.b, stale, 1e-5, 300);
    changed.a.renew_terms_revision();
    (void)reused.solve(changed.a, changed.b, renewed, 1e-5, 300);
    (void)other.solve(changed.a, changed.b, expected_changed, 1e-5, 300);
    EXPECT_EQ(renewed, expected_changed);
    if (resmooth)
      EXPECT_EQ(stale, expected_changed);
    else
      EXPECT_NE(stale, expected_changed);
  }
}

TEST(MultigridPcg, PreconditionerWithCouplingsIsSymmetricPositiveDefinite) {
  expect_symmetric_positive_definite(coupled_system(16, 1e6), 13);
}

// Stiff couplings between far particles are what the springs' hierarchy cannot see: with
// only their diagonal blocks in it, the coarse levels miss them; carried into every level,
// they cost CG far fewer iterations.
TEST(MultigridPcg, CouplingsInTheHierarchySaveIterations) {
  const NewtonSystem system = coupled_system(32, 1e4);
  int count[2] = {};
  for (const bool coarse_couplings : {false, true}) {
    MultigridPcg pcg(system.model, {.coarse_couplings = coarse_couplings});
    Eigen::VectorXd x(system.b.size());
    const PcgResult result = pcg.solve(system.a, system.b, x, 1e-6, 3000);
    EXPECT_TRUE(result.converged);
    count[coarse_couplings] = result.iterations;
  }
  EXPECT_LT(count[1], 0.6 * count[0]) << count[0] << " -> " << count[1];
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

// Refining a loose answer goes on from its residual: it reaches the tighter tolerance (the true
// residual, recomputed here) in fewer iterations than solving again from zero, for both
// preconditioners; an answer that already meets the tolerance is returned untouched.
template <class Solver>
void expect_refining_goes_on_from_the_answer(const NewtonSystem& system) {
  Solver solver(system.model);
  const auto true_residual = [&](const Eigen::VectorXd& x) {
    Eigen::VectorXd ax(x.size());
    system.a.multiply(system.model, x, ax);
    return (system.b - ax).norm() / system.b.norm();
  };
  Eigen::VectorXd loose(system.b.size()), tight(system.b.size());
  const PcgResult first = solver.solve(system.a, system.b, loose, 1e-1, 1000);
  ASSERT_TRUE(first.converged);
  const PcgResult fresh = solver.solve(system.a, system.b, tight, 1e-3, 1000);
  ASSERT_TRUE(fresh.converged);

  (void)solver.solve(system.a, system.b, tight, 1e-1, 1000);  // the loose answer again
  EXPECT_EQ(tight, loose);
  const PcgResult refined = solver.refine(system.a, system.b, tight, 1e-3, 1000);
  EXPECT_TRUE(refined.converged);
  EXPECT_LE(true_residual(tight), 1.0001e-3);
  EXPECT_LT(refined.iterations, fresh.iterations);
  EXPECT_GT(refined.iterations, 0);

  const Eigen::VectorXd before = tight;
  const PcgResult again = solver.refine(system.a, system.b, tight, 1e-2, 1000);
  EXPECT_TRUE(again.converged);
  EXPECT_EQ(again.iterations, 0);
  EXPECT_EQ(tight, before);
}

TEST(MultigridPcg, RefiningALooseAnswerGoesOnFromIt) {
  expect_refining_goes_on_from_the_answer<MultigridPcg>(hanging_system(cotton(16, 1e4), 10));
}

TEST(BlockJacobiPcg, RefiningALooseAnswerGoesOnFromIt) {
  expect_refining_goes_on_from_the_answer<BlockJacobiPcg>(hanging_system(cotton(16, 1e4), 10));
}

// Hybrid sweeps (MultigridOptions::sweep_chunk_nodes): a 17 x 17 grid (289 nodes) with a
// chunk size of 64 sweeps four chunks of 72 or 73 nodes on the finest level.
constexpr MultigridOptions kFourChunks{.sweep_chunk_nodes = 64};

Eigen::VectorXd solve_with(const NewtonSystem& system, const MultigridOptions& options) {
  MultigridPcg pcg(system.model, options);
  Eigen::VectorXd x(system.b.size());
  EXPECT_TRUE(pcg.solve(system.a, system.b, x, 1e-8, 300).converged);
  return x;
}

// Two sweeps each way: the second forward sweep starts from the first's values.
constexpr MultigridOptions kFourChunksTwoSweeps{.smoothing_sweeps = 2, .sweep_chunk_nodes = 64};

TEST(MultigridPcg, HybridSweepsMatchTheDirectSolve) {
  expect_matches_direct_solve(hanging_system(cotton(16, 1e4), 10), kFourChunks);
  expect_matches_direct_solve(hanging_system(stiff_bending_sheet(), 10), kFourChunks);
  expect_matches_direct_solve(hanging_system(cotton(16, 1e4), 10), kFourChunksTwoSweeps);
}

TEST(MultigridPcg, HybridSweepsKeepThePreconditionerSymmetricPositiveDefinite) {
  expect_symmetric_positive_definite(hanging_system(cotton(16, 1e4), 10), 19, kFourChunks);
  expect_symmetric_positive_definite(hanging_system(stiff_bending_sheet(), 10), 23, kFourChunks);
  expect_symmetric_positive_definite(hanging_system(cotton(16, 1e4), 10), 29,
                                     kFourChunksTwoSweeps);
}

// The chunks depend on the level's size alone: one, two and three threads give the same bits.
// A level smaller than two chunks is swept whole, as without chunks.
TEST(MultigridPcg, HybridSweepsGiveTheSameBitsOnAnyThreadCount) {
  struct Guard {
    ~Guard() { set_thread_count(0); }
  } guard;
  const NewtonSystem system = hanging_system(cotton(16, 1000.0), 5);
  set_thread_count(1);
  const Eigen::VectorXd serial = solve_with(system, kFourChunks);
  set_thread_count(2);
  EXPECT_EQ(solve_with(system, kFourChunks), serial);
  set_thread_count(3);
  EXPECT_EQ(solve_with(system, kFourChunks), serial);
  const Eigen::VectorXd whole = solve_with(system, {.sweep_chunk_nodes = 0});
  EXPECT_NE(whole, serial);
  EXPECT_EQ(solve_with(system, {.sweep_chunk_nodes = 145}), whole);  // under two chunks
}

// Couplings across the chunks (a cloth folded onto itself): the hybrid sweeps take them as
// their own blocks, with the l1 term.
TEST(MultigridPcg, HybridSweepsTakeTheTermsCouplings) {
  const NewtonSystem system = coupled_system(16, 1e5);
  ASSERT_FALSE(system.a.extra.empty());
  const Eigen::VectorXd x = solve_with(system, kFourChunks);
  const Eigen::VectorXd expected = dense_solve(system);
  EXPECT_LE((x - expected).norm(), 1e-6 * expected.norm());
  EXPECT_NE(x, solve_with(system, {.sweep_chunk_nodes = 0}));  // the chunks did sweep
  expect_symmetric_positive_definite(coupled_system(16, 1e6), 31, kFourChunks);
}

}  // namespace
}  // namespace animkit
