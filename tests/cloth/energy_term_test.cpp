// Extra energy terms (energy_term.h): Newton minimizes g plus the terms; the other integrators
// refuse them by name. The term used here adds springs, so each result can be checked against
// the same cloth with those springs built in.
#include "animkit/cloth/energy_term.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/grid_cloth.h"
#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/integrator_registry.h"
#include "animkit/cloth/spring_energy.h"

namespace animkit {
namespace {

// Springs given as a term: a coupling term (off-diagonal blocks), the kind contact adds.
class SpringTerm final : public EnergyTerm {
 public:
  explicit SpringTerm(std::vector<SpringDesc> springs) : springs_(std::move(springs)) {}
  std::string_view name() const override { return "extra springs"; }
  double value(const Eigen::VectorXd& x) const override {
    double energy = 0.0;
    for (const SpringDesc& s : springs_)
      energy += spring_energy(at(x, s.a), at(x, s.b), s.stiffness, s.rest_length);
    return energy;
  }
  void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const override {
    for (const SpringDesc& s : springs_) {
      const Vec3 g = spring_gradient(at(x, s.a), at(x, s.b), s.stiffness, s.rest_length);
      gradient.segment<3>(3 * s.a) += g;
      gradient.segment<3>(3 * s.b) -= g;
    }
  }
  void add_hessian(const Eigen::VectorXd& x, bool projected,
                   std::vector<HessianBlock>& blocks) const override {
    for (const SpringDesc& s : springs_) {
      const Eigen::Matrix3d k =
          spring_hessian_block(at(x, s.a), at(x, s.b), s.stiffness, s.rest_length, projected);
      blocks.push_back({s.a, s.a, k});
      blocks.push_back({s.b, s.b, k});
      blocks.push_back({s.a, s.b, -k});
    }
  }

 private:
  static Vec3 at(const Eigen::VectorXd& x, int i) { return x.segment<3>(3 * i); }
  std::vector<SpringDesc> springs_;
};

// The lab's cloth with its springs split: the model keeps the first ones, the term gets the
// rest (long-range ones included), so the term couples particles the model's pattern links.
struct SplitCloth {
  ClothDesc whole, model_part;
  std::vector<SpringDesc> term_part;
};

SplitCloth split_cloth() {
  SplitCloth split;
  split.whole = make_grid_cloth({.cells = 6, .stiffness = 3000.0, .damping = 0.0});
  split.model_part = split.whole;
  split.model_part.springs.clear();
  for (std::size_t s = 0; s < split.whole.springs.size(); ++s) {
    SpringDesc spring = split.whole.springs[s];
    if (spring.rest_length < 0.0) {  // "the distance in the description": the term needs it
      spring.rest_length =
          (split.whole.particles[spring.a].position - split.whole.particles[spring.b].position)
              .norm();
    }
    (s % 3 == 0 ? split.term_part : split.model_part.springs).push_back(spring);
  }
  return split;
}

class NewtonWithTerms : public testing::TestWithParam<std::string> {};

TEST_P(NewtonWithTerms, ReachTheSameStatesAsTheSpringsBuiltIn) {
  const SplitCloth split = split_cloth();
  IntegratorSettings settings = find_integrator(GetParam())->defaults;
  // Tight, but above rounding: the two systems sum the same springs in different orders, and
  // clang (the sanitizer tree) fuses multiply-adds, so at 1e-10 one of them stalled at frame 16.
  set_tolerance(settings, 1e-9);
  auto reference = ClothSimulator::create(split.whole, {settings, 0});
  auto with_term = ClothSimulator::create(split.model_part, {settings, 0});
  ASSERT_TRUE(reference && with_term);
  ASSERT_TRUE(with_term->add_energy_term(std::make_shared<SpringTerm>(split.term_part)));
  for (int frame = 0; frame < 20; ++frame) {
    const auto a = reference->step(1.0 / 30.0);
    const auto b = with_term->step(1.0 / 30.0);
    ASSERT_TRUE(a && b);
    EXPECT_TRUE(b->converged) << "frame " << frame;
  }
  const double difference =
      (reference->state().positions - with_term->state().positions).cwiseAbs().maxCoeff();
  EXPECT_LT(difference, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(Newton, NewtonWithTerms,
                         testing::Values("implicit-pcg", "implicit-multigrid", "implicit-direct"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

TEST(EnergyTerms, JoinTheGradientAndHessianOfG) {
  // The potential with the term against the potential of the springs built in, at a deformed x.
  const SplitCloth split = split_cloth();
  const auto whole = build_cloth(split.whole);
  const auto part = build_cloth(split.model_part);
  ASSERT_TRUE(whole && part);
  IncrementalPotential reference(whole->model), with_term(part->model);
  with_term.add_term(std::make_shared<SpringTerm>(split.term_part));
  ClothState state = whole->state;
  for (Eigen::Index k = 0; k < state.velocities.size(); ++k)
    state.velocities[k] = 0.3 * std::sin(1.7 * static_cast<double>(k));
  reference.prepare(state, 0.05);
  with_term.prepare(state, 0.05);
  Eigen::VectorXd x = reference.predicted();
  for (Eigen::Index k = 0; k < x.size(); ++k) x[k] += 0.02 * std::cos(2.3 * static_cast<double>(k));
  const Eigen::VectorXd step = 1e-3 * Eigen::VectorXd::Ones(x.size());
  EXPECT_NEAR(with_term.value(x), reference.value(x), 1e-9 * std::abs(reference.value(x)));
  EXPECT_NEAR(with_term.difference(x, step), reference.difference(x, step),
              1e-7 * std::abs(reference.difference(x, step)));
  Eigen::VectorXd g_ref(x.size()), g_term(x.size());
  reference.gradient(x, g_ref);
  with_term.gradient(x, g_term);
  EXPECT_LT((g_ref - g_term).norm(), 1e-10 * g_ref.norm());
  // The Hessians act the same on any vector.
  BlockHessian h_ref(whole->model), h_term(part->model);
  reference.hessian(x, h_ref, false);
  with_term.hessian(x, h_term, false);
  Eigen::VectorXd p(x.size()), y_ref(x.size()), y_term(x.size());
  for (Eigen::Index k = 0; k < p.size(); ++k) p[k] = std::sin(0.37 * static_cast<double>(k));
  h_ref.multiply(whole->model, p, y_ref);
  h_term.multiply(part->model, p, y_term);
  EXPECT_LT((y_ref - y_term).norm(), 1e-10 * y_ref.norm());
}

TEST(EnergyTerms, OtherIntegratorsRefuseThemByName) {
  for (const IntegratorEntry& entry : cloth_integrators()) {
    auto sim = ClothSimulator::create(make_grid_cloth({.cells = 4}), {entry.defaults, 0});
    ASSERT_TRUE(sim);
    const auto added =
        sim->add_energy_term(std::make_shared<SpringTerm>(std::vector<SpringDesc>{}));
    const bool newton = std::holds_alternative<NewtonSettings>(entry.defaults);
    EXPECT_EQ(added.has_value(), newton) << entry.name;
    if (!added) {
      EXPECT_EQ(added.error().message.rfind(std::string(entry.name) + " cannot take", 0), 0u)
          << added.error().message;
    }
  }
  auto sim = ClothSimulator::create(make_grid_cloth({.cells = 4}), {});
  ASSERT_TRUE(sim);
  EXPECT_FALSE(sim->add_energy_term(nullptr));
}

}  // namespace
}  // namespace animkit
