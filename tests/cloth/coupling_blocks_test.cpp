// The multigrid's couplings outside the springs' pattern (src/cloth/coupling_blocks.h): the
// assembled matrix equals the sum of the blocks added (both triangles, duplicates summed), and
// restricting it through a prolongator P gives P^T E P, computed here densely.
// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// with -march=native at -O1 (a false positive in the compiler's own headers, see
// psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "../../src/cloth/coupling_blocks.h"

#include <gtest/gtest.h>

#include <random>

#include "../support/dense_blocks.h"

namespace animkit {
namespace {

using Matrix = BlockSparseMatrix<3, 3>;

Eigen::Matrix3d random_block(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::Matrix3d m;
  for (int k = 0; k < 9; ++k) m(k % 3, k / 3) = normal(rng);
  return m;
}

using testing_support::dense;

// Six nodes, blocks between some of them, one pair added twice and one in both orders.
struct Example {
  CouplingBlocks blocks;
  Eigen::MatrixXd expected = Eigen::MatrixXd::Zero(18, 18);
};

Example example() {
  Example e;
  std::mt19937 rng(3);
  e.blocks.clear(6);
  for (const auto& [r, c] :
       std::vector<std::pair<int, int>>{{0, 5}, {4, 1}, {0, 5}, {2, 3}, {3, 2}}) {
    const Eigen::Matrix3d b = random_block(rng);
    e.blocks.add(r, c, b);
    e.expected.block<3, 3>(3 * r, 3 * c) += b;
    e.expected.block<3, 3>(3 * c, 3 * r) += b.transpose();
  }
  e.blocks.assemble();
  return e;
}

TEST(CouplingBlocks, AssembledMatrixIsTheSymmetricSumOfTheBlocks) {
  const Example e = example();
  const Matrix& full = e.blocks.full();
  EXPECT_EQ(full.block_count(), 6);  // three distinct pairs, both triangles
  EXPECT_LE((dense(full) - e.expected).norm(), 1e-14 * e.expected.norm());
  for (int i = 0; i < full.block_rows; ++i) {
    EXPECT_EQ(full.find(i, i), -1) << "no diagonal blocks";
    for (int k = full.row_start[i] + 1; k < full.row_start[i + 1]; ++k)
      EXPECT_LT(full.column[k - 1], full.column[k]) << "columns ascending in row " << i;
  }
  EXPECT_EQ(dense(full), dense(full).transpose());  // exactly symmetric
}

TEST(CouplingBlocks, RestrictionIsTheGalerkinProduct) {
  const Example e = example();
  // P: six fine nodes onto three coarse ones, some rows reaching two aggregates.
  std::mt19937 rng(8);
  const Matrix pattern = block_pattern<3, 3>({{0}, {0, 1}, {1}, {1, 2}, {2}, {0, 2}}, 3);
  Matrix p = pattern;
  for (auto& v : p.values) v = random_block(rng);
  Matrix coarse_a = block_pattern<3, 3>({{0, 1, 2}, {0, 1, 2}, {0, 1, 2}}, 3);
  std::vector<int> diagonal = {coarse_a.find(0, 0), coarse_a.find(1, 1), coarse_a.find(2, 2)};
  CouplingBlocks coarse;
  std::vector<CouplingBlocks::DiagonalPart> within;
  e.blocks.restrict_to(p, coarse, within);
  CouplingBlocks::add_within(within, coarse_a, diagonal);
  const Eigen::MatrixXd expected = dense(p).transpose() * e.expected * dense(p);
  const Eigen::MatrixXd got = dense(coarse.full()) + dense(coarse_a);
  EXPECT_LE((got - expected).norm(), 1e-12 * expected.norm());
  EXPECT_EQ(got, got.transpose());
}

TEST(CouplingBlocks, EmptyAfterClear) {
  CouplingBlocks blocks;
  blocks.clear(4);
  blocks.assemble();
  EXPECT_TRUE(blocks.empty());
  EXPECT_EQ(blocks.full().block_count(), 0);
  Eigen::VectorXd x = Eigen::VectorXd::Ones(12), y = Eigen::VectorXd::Zero(12);
  blocks.full().multiply_add(x, y);
  EXPECT_EQ(y.norm(), 0.0);
}

}  // namespace
}  // namespace animkit
