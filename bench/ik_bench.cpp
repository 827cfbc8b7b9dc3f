// IK per-target cost on the lab's star (400 targets, warm start, reset to rest at the start of
// the shape, as the lab's app runs it), animkit's double solvers against the lab's
// straightforward float versions in the same binary. Prints the ratios at the end.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <map>
#include <string>

#include "animkit/kinematics/ccd.h"
#include "animkit/kinematics/fabrik.h"
#include "animkit/trajectory/lab_shapes.h"
#include "lab_float_ik.h"
#include "ratio_reporter.h"

namespace {

using animkit::Vec3;

const std::vector<Vec3>& star() {
  static const auto targets = animkit::lab_shape_targets(animkit::LabShape::star);
  return targets;
}

const animkit::Chain& arm() {
  static const animkit::Chain chain = *animkit::build_chain(animkit::lab_arm());
  return chain;
}

void set_counters(benchmark::State& state, double solves, double iterations, double converged) {
  // Rate of "solves per microsecond", inverted: microseconds per target.
  state.counters["us_per_target"] = benchmark::Counter(
      solves * 1e-6, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.counters["iters_per_target"] = iterations / solves;
  state.counters["converged"] = converged / solves;
}

// Draws the star once per benchmark iteration; counters give per-target cost and quality.
template <class Solve>
void draw_star(benchmark::State& state, Solve solve) {
  const auto& targets = star();
  const animkit::Pose rest = animkit::rest_pose(arm());
  animkit::Pose pose = rest;
  double iterations = 0, converged = 0, solves = 0;
  for (auto _ : state) {
    pose = rest;
    for (const Vec3& t : targets) {
      const auto result = solve(arm(), pose, t, animkit::IkOptions{});
      iterations += result->iterations;
      converged += result->converged ? 1 : 0;
      ++solves;
    }
    benchmark::DoNotOptimize(pose.global_positions.data());
  }
  set_counters(state, solves, iterations, converged);
}

void BM_CcdStar(benchmark::State& state) { draw_star(state, animkit::solve_ccd); }
void BM_FabrikStar(benchmark::State& state) { draw_star(state, animkit::solve_fabrik); }

template <int (*Solve)(animkit::bench::LabFloatArm&, const Eigen::Vector3f&, int, float)>
void lab_float_star(benchmark::State& state) {
  std::vector<Eigen::Vector3f> targets;
  for (const Vec3& t : star()) targets.push_back(t.cast<float>());
  const auto rest = animkit::bench::LabFloatArm::rest();
  auto arm_state = rest;
  double iterations = 0, converged = 0, solves = 0;
  for (auto _ : state) {
    arm_state = rest;
    for (const auto& t : targets) {
      iterations += Solve(arm_state, t, 100, 1e-4f);
      converged += (arm_state.end_effector() - t).norm() <= 1e-4f ? 1 : 0;
      ++solves;
    }
    benchmark::DoNotOptimize(arm_state.global_position.data());
  }
  set_counters(state, solves, iterations, converged);
}

BENCHMARK(BM_CcdStar);
BENCHMARK(BM_FabrikStar);
BENCHMARK(lab_float_star<animkit::bench::lab_ccd>)->Name("BM_LabFloatCcdStar");
BENCHMARK(lab_float_star<animkit::bench::lab_fabrik>)->Name("BM_LabFloatFabrikStar");

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratio("BM_LabFloatCcdStar", "BM_CcdStar", "us_per_target",
                       "lab float CCD / animkit CCD, time per target");
  reporter.print_ratio("BM_LabFloatFabrikStar", "BM_FabrikStar", "us_per_target",
                       "lab float FABRIK / animkit FABRIK, time per target");
  reporter.print_ratio("BM_CcdStar", "BM_FabrikStar", "us_per_target",
                       "animkit CCD / animkit FABRIK, time per target");
  benchmark::Shutdown();
  return 0;
}
