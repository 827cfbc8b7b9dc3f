// The tree IK benchmark: the CMU walk 131_01 (31 joints, End Sites aside; metres) with
// four effectors, the hands (lhand, rhand) and the feet (LeftAnkle, RightAnkle). Each frame's
// targets are that frame's FK (so every set is jointly reachable), the root is put where the
// frame has it, and each solve starts from the previous frame's solution (rest for the first).
// The same frames are solved by animkit (DLS, SDLS, FABRIK, CCD) and by Orocos KDL's tree
// solvers on the same skeleton, with the same tolerance (1e-4 m) and iteration cap (100).
//
// KDL (Debian's liborocos-kdl-dev, linked by this program only): each BVH joint becomes a fixed
// segment carrying its offset, then one revolute segment per rotation channel in the file's
// order (so a frame's Euler angles are KDL's joint values: 90 of them). The solve is the loop of
// TreeIkSolverPos_NR_JL (FK with TreeFkSolverPos_recursive, a step from TreeIkSolverVel_wdls,
// q += dq) with task-space weights that ignore orientation and the stop test on the largest
// position error, as animkit's; NR_JL's own stop test also wants the orientations, which these
// targets do not give. The WDLS solver is damped (setLambda): undamped it diverges to NaN on
// this skeleton (the kdl_wdls_undamped row shows it). A NaN counts as a failure, and the next
// frame starts from rest.
//
// One benchmark iteration solves the whole clip. Counters: per_frame (wall time per frame),
// converged (fraction of frames within tolerance), max_err_mm (largest final error), nan_frames,
// iters (mean iterations per frame).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <kdl/treefksolverpos_recursive.hpp>
#include <kdl/treeiksolvervel_wdls.hpp>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "animkit/io/bvh.h"
#include "animkit/kinematics/ccd_tree.h"
#include "animkit/kinematics/dls_tree.h"
#include "animkit/kinematics/fabrik_tree.h"
#include "kdl_skeleton.h"
#include "ratio_reporter.h"

namespace {

using animkit::Vec3;
using animkit::bench::kdl;
using animkit::bench::kdl_frame;
using animkit::bench::kdl_model;
using animkit::bench::KdlModel;

constexpr const char* kEffectorNames[] = {"lhand", "rhand", "LeftAnkle", "RightAnkle"};
constexpr double kTolerance = 1e-4;  // metres
constexpr int kMaxIterations = 100;
constexpr double kLambda = animkit::DlsSettings{}.lambda;  // both solvers' damping, metres

struct Clip {
  animkit::BvhClip bvh;
  animkit::Skeleton skeleton;
  std::vector<int> effector_joints;
  std::vector<animkit::SkeletonPose> frames;  // each frame's pose, FK run
};

const Clip& clip() {
  static const Clip c = [] {
    auto bvh = animkit::read_bvh_file(ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh", {.scale = 0.056444});
    if (!bvh) {
      std::fprintf(stderr, "%s\n", bvh.error().message.c_str());
      std::exit(1);
    }
    Clip out{*bvh, *animkit::build_skeleton(bvh->skeleton), {}, {}};
    for (const char* name : kEffectorNames)
      out.effector_joints.push_back(out.skeleton.find_joint(name));
    for (int f = 0; f < bvh->frame_count(); ++f) {
      animkit::SkeletonPose pose = animkit::skeleton_rest_pose(out.skeleton);
      animkit::bvh_frame_to_pose(*bvh, f, pose);
      animkit::skeleton_forward_kinematics(out.skeleton, pose);
      out.frames.push_back(std::move(pose));
    }
    return out;
  }();
  return c;
}

struct Tally {
  int frames = 0, converged = 0, nan_frames = 0;
  double max_error = 0.0, iterations = 0.0;

  void add(double error, bool ok, int iters) {
    ++frames;
    iterations += iters;
    if (std::isnan(error)) {
      ++nan_frames;
      return;
    }
    converged += ok ? 1 : 0;
    max_error = std::max(max_error, error);
  }
  void report(benchmark::State& state) const {
    // Wall seconds per frame (printed with an SI prefix: "25u" is 25 microseconds).
    state.counters["per_frame"] = benchmark::Counter(
        frames, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
    state.counters["converged"] = static_cast<double>(converged) / frames;
    state.counters["max_err_mm"] = 1e3 * max_error;
    state.counters["nan_frames"] = nan_frames;
    state.counters["iters"] = iterations / frames;
  }
};

// ---- animkit ---------------------------------------------------------------------------------

// Solves every frame of the clip with `solve(effectors, pose)` once per benchmark iteration.
template <class Solve>
void animkit_clip(benchmark::State& state, Solve solve) {
  const Clip& c = clip();
  std::vector<animkit::Effector> effectors(c.effector_joints.size());
  Tally tally;
  for (auto _ : state) {
    tally = {};
    animkit::SkeletonPose pose = animkit::skeleton_rest_pose(c.skeleton);
    for (const animkit::SkeletonPose& goal : c.frames) {
      for (int r : c.skeleton.roots()) {
        pose.local_rotations[r] = goal.local_rotations[r];
        pose.local_translations[r] = goal.local_translations[r];
      }
      for (std::size_t e = 0; e < effectors.size(); ++e)
        effectors[e] = {c.effector_joints[e], goal.global_positions[c.effector_joints[e]]};
      auto result = solve(effectors, pose);
      tally.add(result->error, result->converged, result->iterations);
      if (std::isnan(result->error)) pose = animkit::skeleton_rest_pose(c.skeleton);
    }
  }
  tally.report(state);
}

void animkit_dls(benchmark::State& state, animkit::DlsMethod method) {
  const animkit::DlsSettings settings{.method = method,
                                      .max_iterations = kMaxIterations,
                                      .tolerance = kTolerance,
                                      .lambda = kLambda};
  animkit::DlsWorkspace workspace;
  animkit_clip(
      state, [&](const std::vector<animkit::Effector>& effectors, animkit::SkeletonPose& pose) {
        return animkit::solve_dls_tree(clip().skeleton, {effectors}, settings, workspace, pose);
      });
}

// FABRIK for trees with its defaults (the DLS finish on, used only by frames the passes do not
// reach: the `finish` counter is the fraction of frames that needed it).
void animkit_fabrik(benchmark::State& state) {
  animkit::FabrikTreeSettings settings;
  settings.max_iterations = kMaxIterations;
  settings.tolerance = kTolerance;
  animkit::FabrikTreeWorkspace workspace;
  int solves = 0, finished = 0;
  animkit_clip(
      state, [&](const std::vector<animkit::Effector>& effectors, animkit::SkeletonPose& pose) {
        auto result =
            animkit::solve_fabrik_tree(clip().skeleton, {effectors}, settings, workspace, pose);
        ++solves;
        finished += result->finish_iterations > 0 ? 1 : 0;
        return result;
      });
  state.counters["finish"] = static_cast<double>(finished) / solves;
}

void animkit_ccd(benchmark::State& state) {
  animkit::CcdTreeSettings settings;
  settings.max_iterations = kMaxIterations;
  settings.tolerance = kTolerance;
  animkit::CcdTreeWorkspace workspace;
  animkit_clip(
      state, [&](const std::vector<animkit::Effector>& effectors, animkit::SkeletonPose& pose) {
        return animkit::solve_ccd_tree(clip().skeleton, {effectors}, settings, workspace, pose);
      });
}

// ---- KDL -------------------------------------------------------------------------------------

// Both models must be one skeleton: KDL's FK of a frame equals animkit's, in the Hips frame.
void check_same_skeleton(const Clip& c, const KdlModel& m) {
  KDL::TreeFkSolverPos_recursive fk(m.tree);
  double worst = 0.0;
  for (int f = 0; f < c.bvh.frame_count(); f += 97) {
    const KDL::JntArray q = kdl_frame(c.bvh, m, f);
    const animkit::SkeletonPose& pose = c.frames[static_cast<std::size_t>(f)];
    for (int j = 0; j < c.skeleton.joint_count(); ++j) {
      KDL::Frame frame;
      fk.JntToCart(q, frame, m.tips[j]);
      const Vec3 ours = pose.global_rotations[0].conjugate() *
                        (pose.global_positions[j] - pose.global_positions[0]);
      worst = std::max(worst, (ours - Vec3(frame.p.x(), frame.p.y(), frame.p.z())).norm());
    }
  }
  if (worst > 1e-9) {
    std::fprintf(stderr, "KDL's skeleton differs from animkit's by %g m\n", worst);
    std::exit(1);
  }
}

void kdl_tree(benchmark::State& state, double lambda) {
  const Clip& c = clip();
  const KdlModel m = kdl_model(c.bvh, c.skeleton);
  check_same_skeleton(c, m);
  std::vector<std::string> endpoints;
  for (int j : c.effector_joints) endpoints.push_back(m.tips[j]);
  KDL::TreeFkSolverPos_recursive fk(m.tree);
  KDL::TreeIkSolverVel_wdls wdls(m.tree, endpoints);
  wdls.setLambda(lambda);
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero(6 * endpoints.size(), 6 * endpoints.size());
  for (std::size_t e = 0; e < endpoints.size(); ++e)
    weights.block<3, 3>(6 * e, 6 * e).setIdentity();  // position rows only
  wdls.setWeightTS(weights);
  // Targets in the Hips frame (KDL's base): the root stays where the frame puts it.
  std::vector<std::vector<KDL::Vector>> targets;
  for (const animkit::SkeletonPose& goal : c.frames) {
    auto& t = targets.emplace_back();
    for (int j : c.effector_joints) {
      t.push_back(kdl(goal.global_rotations[0].conjugate() *
                      (goal.global_positions[j] - goal.global_positions[0])));
    }
  }
  KDL::JntArray q(m.joints), dq(m.joints);
  KDL::Twists twists;
  KDL::Frame frame;
  Tally tally;
  for (auto _ : state) {
    tally = {};
    q.data.setZero();
    for (const auto& t : targets) {
      int it = 0;
      double error = 0.0;
      for (;; ++it) {
        error = 0.0;
        for (std::size_t e = 0; e < endpoints.size(); ++e) {
          fk.JntToCart(q, frame, endpoints[e]);
          const KDL::Vector d = t[e] - frame.p;
          error = std::isnan(error) ? error : std::max(error, d.Norm());
          if (std::isnan(d.Norm())) error = std::nan("");
          twists[endpoints[e]] = KDL::Twist(d, KDL::Vector::Zero());
        }
        if (!(error > kTolerance) || it == kMaxIterations) break;
        wdls.CartToJnt(q, twists, dq);
        KDL::Add(q, dq, q);
      }
      tally.add(error, error <= kTolerance, it);
      if (std::isnan(error)) q.data.setZero();
    }
  }
  tally.report(state);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RegisterBenchmark(
      "tree_ik/animkit_dls",
      [](benchmark::State& s) { animkit_dls(s, animkit::DlsMethod::damped); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark(
      "tree_ik/animkit_sdls",
      [](benchmark::State& s) { animkit_dls(s, animkit::DlsMethod::selective); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("tree_ik/animkit_fabrik", animkit_fabrik)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("tree_ik/animkit_ccd", animkit_ccd)
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  benchmark::RegisterBenchmark("tree_ik/kdl_wdls",
                               [](benchmark::State& s) { kdl_tree(s, kLambda); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  // Undamped, to show why the comparison damps it: its NaN frames are failures.
  benchmark::RegisterBenchmark("tree_ik/kdl_wdls_undamped",
                               [](benchmark::State& s) { kdl_tree(s, 0.0); })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime();
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratio("tree_ik/kdl_wdls", "tree_ik/animkit_dls", "time",
                       "KDL tree WDLS / animkit DLS, time per frame");
  reporter.print_ratio("tree_ik/kdl_wdls", "tree_ik/animkit_sdls", "time",
                       "KDL tree WDLS / animkit SDLS, time per frame");
  reporter.print_ratio("tree_ik/kdl_wdls", "tree_ik/animkit_fabrik", "time",
                       "KDL tree WDLS / animkit FABRIK, time per frame");
  reporter.print_ratio("tree_ik/kdl_wdls", "tree_ik/animkit_ccd", "time",
                       "KDL tree WDLS / animkit CCD, time per frame");
  benchmark::Shutdown();
  return 0;
}
