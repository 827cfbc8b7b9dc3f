// The multigrid's Galerkin products (src/cloth/galerkin_product.h): P^T A P for fixed
// patterns equals the dense product, with general blocks in P and with P's blocks multiples of
// the identity given as scales (the smoothed aggregation's prolongators), which take the
// scaling path.
// GCC 12's AVX-512 intrinsics trip -Wuninitialized when Eigen's dense products are inlined
// with -march=native at -O1 (a false positive in the compiler's own headers, see
// psd_projection.cpp).
#pragma GCC diagnostic ignored "-Wuninitialized"
#include "../../src/cloth/galerkin_product.h"

#include <gtest/gtest.h>

#include <random>

#include "../support/dense_blocks.h"

namespace animkit {
namespace {

using Matrix = BlockSparseMatrix<3, 3>;

using testing_support::dense;

// A symmetric 8-node chain (each node coupled to the next two) and a prolongator onto three
// aggregates whose rows reach one or two of them.
struct GalerkinExample {
  Matrix a = block_pattern<3, 3>({{0, 1, 2},
                                  {0, 1, 2, 3},
                                  {0, 1, 2, 3, 4},
                                  {1, 2, 3, 4, 5},
                                  {2, 3, 4, 5, 6},
                                  {3, 4, 5, 6, 7},
                                  {4, 5, 6, 7},
                                  {5, 6, 7}},
                                 8);
  Matrix p = block_pattern<3, 3>({{0}, {0, 1}, {0, 1}, {1}, {1, 2}, {1, 2}, {2}, {2}}, 3);
};

GalerkinExample example(std::mt19937& rng) {
  std::normal_distribution<double> normal;
  GalerkinExample e;
  for (int i = 0; i < e.a.block_rows; ++i) {
    for (int k = e.a.row_start[i]; k < e.a.row_start[i + 1]; ++k) {
      const int j = e.a.column[k];
      if (j < i) continue;
      Eigen::Matrix3d b;
      for (int c = 0; c < 9; ++c) b(c % 3, c / 3) = normal(rng);
      if (j == i) b = b * b.transpose() + Eigen::Matrix3d::Identity();
      e.a.values[k] = b;
      e.a.values[e.a.find(j, i)] = b.transpose();
    }
  }
  return e;
}

TEST(GalerkinProduct, GeneralBlocksGiveTheDenseProduct) {
  std::mt19937 rng(4);
  GalerkinExample e = example(rng);
  std::normal_distribution<double> normal;
  for (auto& block : e.p.values) {
    for (int c = 0; c < 9; ++c) block(c % 3, c / 3) = normal(rng);
  }
  GalerkinProduct<3, 3> product;
  Matrix coarse = product.analyze(e.a, e.p);
  product.compute(e.a, e.p, coarse);
  const Eigen::MatrixXd expected = dense(e.p).transpose() * dense(e.a) * dense(e.p);
  EXPECT_LE((dense(coarse) - expected).norm(), 1e-13 * expected.norm());
}

TEST(GalerkinProduct, ScaledIdentityBlocksGiveTheDenseProductByScaling) {
  std::mt19937 rng(5);
  const GalerkinExample e = example(rng);
  Matrix p = e.p;
  std::vector<double> scale;
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (auto& block : p.values) {
    scale.push_back(uniform(rng));
    block = scale.back() * Eigen::Matrix3d::Identity();
  }
  GalerkinProduct<3, 3> product;
  Matrix general = product.analyze(e.a, p), scaled = general;
  product.compute(e.a, p, general);
  product.compute(e.a, p, scaled, &scale);
  const Eigen::MatrixXd expected = dense(p).transpose() * dense(e.a) * dense(p);
  EXPECT_LE((dense(scaled) - expected).norm(), 1e-13 * expected.norm());
  EXPECT_LE((dense(scaled) - dense(general)).norm(), 1e-13 * expected.norm());
  // The scales are what the products use: other scales give another matrix.
  std::vector<double> doubled = scale;
  for (double& s : doubled) s *= 2.0;
  product.compute(e.a, p, scaled, &doubled);
  EXPECT_LE((dense(scaled) - 4.0 * expected).norm(), 1e-13 * expected.norm());
}

}  // namespace
}  // namespace animkit
