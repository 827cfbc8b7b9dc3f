// The hooks contact needs from Newton's stages (energy_term.h): a term that bounds the step
// (EnergyTerm::max_step) is never stepped past, neither by the start of a substep (the move from
// x_n towards the prediction y) nor by the line search or its extension, and the term sees every
// new iterate (EnergyTerm::update) before g's gradient is taken there. The term is a floor with
// IPC's log barrier (Li et al. 2020) on each particle's height: the simplest contact there is.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string_view>
#include <vector>

#include "animkit/cloth/cloth_simulator.h"
#include "animkit/cloth/energy_term.h"
#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

// b(d) = -kappa (d - dhat)^2 ln(d / dhat) for 0 < d < dhat on the height d = y - floor;
// infinite at or below the floor. max_step keeps every particle above 10% of its height.
class FloorBarrier final : public EnergyTerm {
 public:
  FloorBarrier(double floor, double dhat, double kappa)
      : floor_(floor), dhat_(dhat), kappa_(kappa) {}
  std::string_view name() const override { return "floor barrier"; }

  void update(const Eigen::VectorXd& x) override {
    ++updates;
    lowest_seen = std::min(lowest_seen, lowest(x));
  }
  double max_step(const Eigen::VectorXd& x, const Eigen::VectorXd& step) override {
    double bound = 1.0;
    for (Eigen::Index i = 1; i < x.size(); i += 3) {
      const double d = x[i] - floor_;
      // Exact for a plane: the height is linear along the step.
      if (step[i] < 0.0) bound = std::min(bound, 0.9 * d / -step[i]);
    }
    return bound;
  }
  double value(const Eigen::VectorXd& x) const override {
    double energy = 0.0;
    for (Eigen::Index i = 1; i < x.size(); i += 3) {
      const double d = x[i] - floor_;
      if (d <= 0.0) return std::numeric_limits<double>::infinity();
      if (d < dhat_) energy -= kappa_ * (d - dhat_) * (d - dhat_) * std::log(d / dhat_);
    }
    return energy;
  }
  void add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const override {
    for (Eigen::Index i = 1; i < x.size(); i += 3) {
      const double d = x[i] - floor_;
      if (d < dhat_)
        gradient[i] -= kappa_ * ((d - dhat_) * (2.0 * std::log(d / dhat_) - dhat_ / d + 1.0));
    }
  }
  void add_hessian(const Eigen::VectorXd& x, bool /*projected*/,
                   std::vector<HessianBlock>& blocks) const override {
    for (Eigen::Index i = 1; i < x.size(); i += 3) {
      const double d = x[i] - floor_;
      if (d >= dhat_) continue;
      // b'' = -kappa (2 ln(d / dhat) + (d - dhat)(3d + dhat) / d^2), positive below dhat.
      const double second =
          -kappa_ * (2.0 * std::log(d / dhat_) + (d - dhat_) * (3.0 * d + dhat_) / (d * d));
      HessianBlock block;
      block.row = block.col = static_cast<int>(i / 3);
      block.value(1, 1) = second;
      blocks.push_back(block);
    }
  }

  double lowest(const Eigen::VectorXd& x) const {
    double y = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = 1; i < x.size(); i += 3) y = std::min(y, x[i] - floor_);
    return y;
  }

  int updates = 0;
  double lowest_seen = std::numeric_limits<double>::infinity();

 private:
  double floor_, dhat_, kappa_;
};

TEST(StepBound, AClothThrownAtABarrierFloorNeverReachesIt) {
  // A small stiff sheet 5 cm above the floor, thrown down at 20 m/s with 1/30 s steps: the
  // prediction y lies 67 cm below the floor, so only the bounds keep it above.
  ClothDesc desc = make_grid_cloth({.cells = 6, .stiffness = 1000.0, .gravity = 9.81});
  for (ParticleDesc& p : desc.particles) {
    p.position.y() = 0.05;
    p.velocity = Vec3(0.0, -20.0, 0.0);
    p.pinned = false;
  }
  auto sim = ClothSimulator::create(desc, {});
  ASSERT_TRUE(sim) << sim.error().message;
  auto floor = std::make_shared<FloorBarrier>(0.0, 0.01, 10.0);
  ASSERT_TRUE(sim->add_energy_term(floor));

  for (int step = 0; step < 30; ++step) {
    const int updates_before = floor->updates;
    const auto report = sim->step(1.0 / 30.0);
    ASSERT_TRUE(report) << report.error().message;
    // Every iterate Newton reached was shown to the term: the start and each accepted step.
    EXPECT_EQ(floor->updates - updates_before, report->newton_iterations + 1);
    EXPECT_GT(floor->lowest(sim->state().positions), 0.0) << "step " << step;
    if (step == 0) {
      EXPECT_LT(report->step_bound_min, 0.1);  // the start itself was bounded
    }
  }
  EXPECT_GT(floor->lowest_seen, 0.0);  // no iterate of any step touched the floor
  // It comes to rest on the floor, within the barrier's reach, not above it.
  EXPECT_LT(floor->lowest(sim->state().positions), 0.01);
}

TEST(StepBound, WithoutTermsNothingIsBounded) {
  auto sim = ClothSimulator::create(make_grid_cloth({.cells = 6}), {});
  ASSERT_TRUE(sim);
  const auto report = sim->step(1.0 / 60.0);
  ASSERT_TRUE(report);
  EXPECT_EQ(report->step_bound_min, 1.0);
  EXPECT_EQ(report->ms_step_bound, 0.0);
}

}  // namespace
}  // namespace animkit
