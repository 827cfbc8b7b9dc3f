#include "animkit/cloth/incremental_potential.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>

#include "animkit/cloth/energy_term.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/hessian_pattern.h"

namespace animkit {
namespace {

// A small lab-like cloth, moving and deformed so every term of g is exercised.
class IncrementalPotentialTest : public testing::Test {
 protected:
  void SetUp() override {
    // With bends along a grid line (its pairs are springs), along a diagonal (its outer
    // pair is not: build_cloth adds a coupling-only spring for it), and a four-particle bend
    // with unequal weights (a mesh's edge element, one of its pairs joined by no spring).
    ClothDesc desc = make_grid_cloth({.cells = 3, .damping = 0.7});
    desc.bends = {
        line_bend(grid_index(3, 1, 0), grid_index(3, 1, 1), grid_index(3, 1, 2), 40.0),
        line_bend(grid_index(3, 0, 0), grid_index(3, 1, 1), grid_index(3, 2, 2), 25.0),
        {{grid_index(3, 1, 1), grid_index(3, 2, 1), grid_index(3, 2, 2), grid_index(3, 1, 0)},
         {0.7, 1.3, -1.1, -0.9},
         30.0}};
    auto built = build_cloth(desc);
    ASSERT_TRUE(built);
    model = built->model;
    state = built->state;
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (Eigen::Index i = 0; i < state.positions.size(); ++i) {
      state.positions[i] += u(rng);
      state.velocities[i] = 10.0 * u(rng);
    }
    x = state.positions;
    for (Eigen::Index i = 0; i < x.size(); ++i) x[i] += u(rng);
  }
  // g's Hessian at x, by blocks and assembled into a pattern of the given layout.
  struct Assembled {
    BlockHessian blocks;
    HessianPattern pattern;
  };
  Assembled hessian_at_x(bool projected, PatternLayout layout = PatternLayout::full) const {
    IncrementalPotential g(model);
    g.prepare(state, h);
    Assembled a{BlockHessian(model), build_hessian_pattern(model, layout)};
    g.hessian(x, a.blocks, projected);
    a.pattern.assign(a.blocks);
    return a;
  }

  ClothModel model;
  ClothState state;
  Eigen::VectorXd x;
  static constexpr double h = 1.0 / 60.0;
};

TEST_F(IncrementalPotentialTest, GradientMatchesFiniteDifferencesOfG) {
  IncrementalPotential g(model);
  g.prepare(state, h);
  Eigen::VectorXd gradient(x.size());
  g.gradient(x, gradient);
  constexpr double step = 1e-7;
  for (int p = 0; p < model.particle_count(); ++p) {
    for (int c = 0; c < 3; ++c) {
      const Eigen::Index i = 3 * p + c;
      if (model.pinned[p]) {
        EXPECT_EQ(gradient[i], 0.0);  // pinned particles are not unknowns
        continue;
      }
      Eigen::VectorXd plus = x, minus = x;
      plus[i] += step;
      minus[i] -= step;
      const double numeric = (g.value(plus) - g.value(minus)) / (2 * step);
      EXPECT_NEAR(gradient[i], numeric, 1e-5 * (1.0 + std::abs(numeric))) << "entry " << i;
    }
  }
}

TEST_F(IncrementalPotentialTest, HessianMatchesFiniteDifferencesOfTheGradient) {
  IncrementalPotential g(model);
  g.prepare(state, h);
  const Assembled exact = hessian_at_x(/*projected=*/false);
  const Eigen::MatrixXd analytic = Eigen::MatrixXd(exact.pattern.matrix);
  // The matrix-free product agrees with the assembled matrix.
  Eigen::VectorXd product(x.size());
  exact.blocks.multiply(model, x, product);
  EXPECT_LT((product - analytic * x).norm(), 1e-10 * product.norm());
  constexpr double step = 1e-6;
  Eigen::VectorXd plus_gradient(x.size()), minus_gradient(x.size());
  for (int p = 0; p < model.particle_count(); ++p) {
    if (model.pinned[p]) continue;
    for (int c = 0; c < 3; ++c) {
      const Eigen::Index i = 3 * p + c;
      Eigen::VectorXd plus = x, minus = x;
      plus[i] += step;
      minus[i] -= step;
      g.gradient(plus, plus_gradient);
      g.gradient(minus, minus_gradient);
      const Eigen::VectorXd column = (plus_gradient - minus_gradient) / (2 * step);
      for (int q = 0; q < model.particle_count(); ++q) {
        if (model.pinned[q]) continue;  // eliminated rows
        for (int r = 0; r < 3; ++r) {
          const Eigen::Index j = 3 * q + r;
          EXPECT_NEAR(analytic(j, i), column[j], 1e-4 * (1.0 + std::abs(column[j])))
              << "entry (" << j << ", " << i << ")";
        }
      }
    }
  }
  EXPECT_LT((analytic - analytic.transpose()).norm(), 1e-9 * analytic.norm());
}

TEST_F(IncrementalPotentialTest, UpperAmdLayoutHoldsTheSameMatrix) {
  // The direct solver's layout: upper triangle in a fill-reducing order. Mirrored and put
  // back in particle order, it must be the full matrix, entry for entry (up to the last bit:
  // fused multiply-adds can round K(i,j) and K(j,i) apart).
  const HessianPattern upper = hessian_at_x(false, PatternLayout::upper_amd).pattern;
  const Eigen::MatrixXd expected(hessian_at_x(false).pattern.matrix);
  Eigen::MatrixXd reordered = Eigen::MatrixXd(upper.matrix).selfadjointView<Eigen::Upper>();
  const auto n = expected.rows();
  ASSERT_EQ(upper.order.size(), static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < n; ++j) {
      ASSERT_NEAR(reordered(upper.order[i], upper.order[j]), expected(i, j),
                  1e-14 * expected.cwiseAbs().maxCoeff())
          << i << ", " << j;
    }
  }
}

TEST_F(IncrementalPotentialTest, ProjectedHessianIsPositiveDefinite) {
  const Eigen::LLT<Eigen::MatrixXd> llt{
      Eigen::MatrixXd(hessian_at_x(/*projected=*/true).pattern.matrix)};
  EXPECT_EQ(llt.info(), Eigen::Success);
}

// A term whose Hessian blocks tell `projected` apart (one diagonal and one coupling block,
// doubled when projected) and that says whether they may be kept for the projected retry.
class ProjectionMarkerTerm : public EnergyTerm {
 public:
  explicit ProjectionMarkerTerm(bool ignores_projection)
      : ignores_projection_(ignores_projection) {}
  std::string_view name() const override { return "marker"; }
  double value(const Eigen::VectorXd& /*x*/) const override { return 0.0; }
  void add_gradient(const Eigen::VectorXd& /*x*/, Eigen::VectorXd& /*gradient*/) const override {}
  void add_hessian(const Eigen::VectorXd& /*x*/, bool projected,
                   std::vector<HessianBlock>& blocks) const override {
    const double scale = projected && !ignores_projection_ ? 2.0 : 1.0;
    blocks.push_back({1, 1, scale * 0.3 * Eigen::Matrix3d::Identity()});
    blocks.push_back({1, 6, scale * 0.1 * Eigen::Matrix3d::Ones()});
  }
  bool hessian_ignores_projection() const override { return ignores_projection_; }

 private:
  bool ignores_projection_;
};

// Newton's retry turns the exact Hessian into the projected one in place: the same bits as
// assembling the projected one, whether the terms' blocks are kept or redone.
TEST_F(IncrementalPotentialTest, ProjectingInPlaceGivesTheProjectedHessian) {
  for (const bool ignores_projection : {true, false}) {
    IncrementalPotential g(model);
    g.add_term(std::make_shared<ProjectionMarkerTerm>(ignores_projection));
    g.prepare(state, h);
    BlockHessian in_place(model), assembled(model);
    g.hessian(x, in_place, false);
    const std::uint64_t exact_revision = in_place.terms_revision;
    g.project_hessian(x, in_place);
    // Kept blocks keep their revision (the multigrid then keeps their couplings too).
    EXPECT_EQ(in_place.terms_revision == exact_revision, ignores_projection);
    g.hessian(x, assembled, true);
    EXPECT_EQ(in_place.diagonal, assembled.diagonal) << ignores_projection;
    EXPECT_EQ(in_place.coupling, assembled.coupling) << ignores_projection;
    ASSERT_EQ(in_place.extra.size(), assembled.extra.size());
    for (std::size_t k = 0; k < in_place.extra.size(); ++k)
      EXPECT_EQ(in_place.extra[k].value, assembled.extra[k].value) << ignores_projection;
    BlockHessian exact(model);
    g.hessian(x, exact, false);
    EXPECT_NE(exact.coupling, assembled.coupling);  // some springs are compressed at x
  }
}

TEST_F(IncrementalPotentialTest, DifferenceIsTheChangeOfG) {
  IncrementalPotential g(model);
  g.prepare(state, h);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double scale : {1e-1, 1e-3, 1e-6}) {
    Eigen::VectorXd step(x.size());
    for (Eigen::Index i = 0; i < step.size(); ++i) step[i] = scale * u(rng);
    const double direct = g.value(x + step) - g.value(x);
    EXPECT_NEAR(g.difference(x, step), direct,
                1e-9 * std::abs(g.value(x)) + 1e-6 * std::abs(direct));
  }
  // Where subtracting two values of g loses every digit, the difference does not: a step
  // along the gradient of size 1e-10 changes g by about -|grad|^2 1e-10.
  Eigen::VectorXd gradient(x.size());
  g.gradient(x, gradient);
  const Eigen::VectorXd tiny = -1e-10 * gradient;
  const double expected = -1e-10 * gradient.squaredNorm();
  EXPECT_NEAR(g.difference(x, tiny), expected, 1e-6 * std::abs(expected));
}

TEST_F(IncrementalPotentialTest, PredictionIsTheSpecsY) {
  IncrementalPotential g(model);
  g.prepare(state, h);
  for (int p = 0; p < model.particle_count(); ++p) {
    const Vec3 expected = model.pinned[p] ? state.position(p)
                                          : Vec3(state.position(p) + h * state.velocity(p) +
                                                 Vec3(0.0, -h * h * model.gravity, 0.0));
    EXPECT_LT((g.predicted().segment<3>(3 * p) - expected).norm(), 1e-15);
  }
}

}  // namespace
}  // namespace animkit
