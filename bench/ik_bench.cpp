// IK per-target cost on the lab's star (400 targets, warm start, reset to rest at the start of
// the shape, as the lab's app runs it), animkit's double solvers against the lab's
// straightforward float versions in the same binary; and the tree solvers on the same
// arm as a one-branch skeleton, free and with joint limits, against the chain solvers without
// limits (the issue asks that the arm with limits keep the chain's speed within 20%). Prints
// the ratios at the end.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>

#include "animkit/kinematics/ccd.h"
#include "animkit/kinematics/ccd_tree.h"
#include "animkit/kinematics/dls_tree.h"
#include "animkit/kinematics/fabrik.h"
#include "animkit/kinematics/fabrik_tree.h"
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

struct SolveOutcome {
  int iterations;
  bool converged;
};

// Draws the star once per benchmark iteration from `rest`, one `solve_one(state, target)` per
// target; counters give the per-target cost (timed around the solves only) and quality.
template <class ArmState, class SolveOne>
void time_star(benchmark::State& state, const ArmState& rest, SolveOne solve_one) {
  ArmState arm_state = rest;
  double iterations = 0, converged = 0, solves = 0;
  std::chrono::duration<double> seconds{0.0};
  for (auto _ : state) {
    arm_state = rest;
    const auto start = std::chrono::steady_clock::now();
    for (const Vec3& t : star()) {
      const SolveOutcome outcome = solve_one(arm_state, t);
      iterations += outcome.iterations;
      converged += outcome.converged ? 1 : 0;
      ++solves;
    }
    seconds += std::chrono::steady_clock::now() - start;
    benchmark::DoNotOptimize(&arm_state);
  }
  state.counters["us_per_target"] = 1e6 * seconds.count() / solves;
  state.counters["iters_per_target"] = iterations / solves;
  state.counters["converged"] = converged / solves;
}

template <class Solver>
void animkit_star(benchmark::State& state, Solver solver) {
  time_star(state, animkit::rest_pose(arm()), [&](animkit::Pose& pose, const Vec3& t) {
    const auto result = solver(arm(), pose, t, animkit::IkOptions{});
    return SolveOutcome{result->iterations, result->converged};
  });
}

void BM_CcdStar(benchmark::State& state) {
  animkit_star(state, animkit::solve_ccd);
}
void BM_FabrikStar(benchmark::State& state) {
  animkit_star(state, animkit::solve_fabrik);
}

// ---- Tree solvers on the lab's arm ----------------------------------------------------------

const animkit::Skeleton& arm_skeleton() {
  static const animkit::Skeleton s =
      *animkit::build_skeleton(animkit::skeleton_desc_from_chain(animkit::lab_arm()));
  return s;
}

// Limits an arm might have: the root (the shoulder) free, every other joint a ball whose bone
// may swing 1.2 rad from rest and twist +-0.5 rad; the star stays within reach (`converged`).
const std::vector<animkit::JointLimit>& arm_limits() {
  static const std::vector<animkit::JointLimit> limits = [] {
    const animkit::Skeleton& s = arm_skeleton();
    std::vector<animkit::JointLimit> out(static_cast<std::size_t>(s.joint_count()),
                                         animkit::FreeJoint{});
    for (int j = 1; j < s.joint_count(); ++j)
      out[static_cast<std::size_t>(j)] = animkit::BallLimit{-Vec3::UnitY(), 1.2, -0.5, 0.5};
    return out;
  }();
  return limits;
}

// The lab's loop through a tree solver: one effector on the arm's end, `limits` or none.
template <class Settings, class Workspace, class Solve>
void tree_star(benchmark::State& state, bool limited, Solve solve) {
  const animkit::Skeleton& s = arm_skeleton();
  const int end = s.joint_count() - 1;
  Settings settings;
  Workspace workspace;
  std::vector<animkit::Effector> effectors{animkit::Effector{end, Vec3::Zero()}};
  std::span<const animkit::JointLimit> limits;
  if (limited) limits = arm_limits();
  time_star(state, animkit::skeleton_rest_pose(s), [&](animkit::SkeletonPose& pose, const Vec3& t) {
    effectors[0].position = t;
    const auto result =
        solve(s, animkit::TreeIkProblem{effectors, limits}, settings, workspace, pose);
    return SolveOutcome{result->iterations, result->converged};
  });
}

void BM_TreeFabrikStar(benchmark::State& state) {
  tree_star<animkit::FabrikTreeSettings, animkit::FabrikTreeWorkspace>(state, state.range(0) != 0,
                                                                       animkit::solve_fabrik_tree);
}
void BM_TreeCcdStar(benchmark::State& state) {
  tree_star<animkit::CcdTreeSettings, animkit::CcdTreeWorkspace>(state, state.range(0) != 0,
                                                                 animkit::solve_ccd_tree);
}
void BM_TreeDlsStar(benchmark::State& state) {
  tree_star<animkit::DlsSettings, animkit::DlsWorkspace>(state, state.range(0) != 0,
                                                         animkit::solve_dls_tree);
}

// The lab's float solvers on the same targets, cast to float.
template <int (*Solve)(animkit::bench::LabFloatArm&, const Eigen::Vector3f&, int, float)>
void lab_float_star(benchmark::State& state) {
  time_star(state, animkit::bench::LabFloatArm::rest(),
            [](animkit::bench::LabFloatArm& lab_arm, const Vec3& t) {
              const Eigen::Vector3f target = t.cast<float>();
              const int iterations = Solve(lab_arm, target, 100, 1e-4f);
              return SolveOutcome{iterations, (lab_arm.end_effector() - target).norm() <= 1e-4f};
            });
}

BENCHMARK(BM_CcdStar);
BENCHMARK(BM_FabrikStar);
BENCHMARK(BM_TreeFabrikStar)->ArgName("limits")->Arg(0)->Arg(1);
BENCHMARK(BM_TreeCcdStar)->ArgName("limits")->Arg(0)->Arg(1);
BENCHMARK(BM_TreeDlsStar)->ArgName("limits")->Arg(0)->Arg(1);
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
  reporter.print_ratio("BM_TreeFabrikStar/limits:1", "BM_FabrikStar", "us_per_target",
                       "tree FABRIK with limits / chain FABRIK, time per target");
  reporter.print_ratio("BM_TreeFabrikStar/limits:0", "BM_FabrikStar", "us_per_target",
                       "tree FABRIK without limits / chain FABRIK, time per target");
  reporter.print_ratio("BM_TreeCcdStar/limits:1", "BM_CcdStar", "us_per_target",
                       "tree CCD with limits / chain CCD, time per target");
  reporter.print_ratio("BM_TreeCcdStar/limits:0", "BM_CcdStar", "us_per_target",
                       "tree CCD without limits / chain CCD, time per target");
  reporter.print_ratio("BM_TreeDlsStar/limits:1", "BM_FabrikStar", "us_per_target",
                       "tree DLS with limits / chain FABRIK, time per target");
  benchmark::Shutdown();
  return 0;
}
