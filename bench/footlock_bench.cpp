// Foot locking of the whole CMU walk 131_01 (994 frames, both feet): detection, the two-bone
// solves, and the metrics, as `animkit footlock` runs them, with the workspace reused between
// runs (the CLI's case is one run: see BM_FootLockWalkColdWorkspace). The target is 50 ms per
// clip. The clip is read once, outside the timing.
//
// Side by side with Orocos KDL (BM_FootLockTargetsKdl): the ankle positions animkit's lock puts
// the legs at, on every frame a lock moves a leg, solved by KDL's ChainIkSolverPos_LMA on that
// leg (the hip and knee rotation channels: 6 joints) from the frame's captured angles, position
// only (LMA's own stop at 1e-5; "converged" counts solves ending within 0.1 mm). Only KDL's solves are timed (not detection or metrics), so the ratio
// favours KDL.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>
#include <kdl/chain.hpp>
#include <kdl/chainfksolverpos_recursive.hpp>
#include <kdl/chainiksolverpos_lma.hpp>
#include <vector>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/kinematics/foot_lock.h"
#include "kdl_skeleton.h"
#include "ratio_reporter.h"

namespace {

struct Walk {
  animkit::BvhClip bvh;
  animkit::Skeleton skeleton;
  animkit::BipedLegs legs;
  animkit::SkeletalMotion motion;
};

const Walk* walk() {
  static const std::optional<Walk> loaded = []() -> std::optional<Walk> {
    const std::filesystem::path path = ANIMKIT_TEST_DATA_DIR "/cmu/131_01.bvh";
    auto clip = animkit::read_bvh_file(path, {.scale = 0.056444});
    if (!clip) {
      std::fprintf(stderr, "%s\n", clip.error().message.c_str());
      return std::nullopt;
    }
    auto skeleton = animkit::build_skeleton(clip->skeleton);
    auto legs = skeleton ? animkit::find_biped_legs(*skeleton) : std::unexpected(skeleton.error());
    if (!legs) return std::nullopt;
    return Walk{*clip, *skeleton, *legs, animkit::motion_from_bvh(*clip)};
  }();
  return loaded ? &*loaded : nullptr;
}

void lock_walk(benchmark::State& state, bool reuse_workspace) {
  const Walk* w = walk();
  if (w == nullptr) {
    state.SkipWithError("the CMU walk is not here");
    return;
  }
  animkit::FootLockWorkspace workspace;
  animkit::SkeletalMotion out;
  for (auto _ : state) {
    if (!reuse_workspace) workspace = {};
    auto result = animkit::lock_feet(w->skeleton, w->legs, w->motion, {}, workspace, out);
    benchmark::DoNotOptimize(result);
  }
  state.counters["frames"] = w->motion.frame_count();
}

void BM_FootLockWalk(benchmark::State& state) {
  lock_walk(state, true);
}
void BM_FootLockWalkColdWorkspace(benchmark::State& state) {
  lock_walk(state, false);
}

// One leg's solve for KDL: its chain from the hip's parent to the ankle, the target in that
// chain's base frame, and the captured angles to start from.
struct KdlLegSolve {
  int leg = 0;
  KDL::Vector target;
  KDL::JntArray start;
};

void BM_FootLockTargetsKdl(benchmark::State& state) {
  using animkit::Vec3;
  using animkit::bench::kdl;
  const Walk* w = walk();
  if (w == nullptr) {
    state.SkipWithError("the CMU walk is not here");
    return;
  }
  // animkit's lock, once, for its targets.
  animkit::FootLockWorkspace workspace;
  animkit::SkeletalMotion locked;
  const auto lock = animkit::lock_feet(w->skeleton, w->legs, w->motion, {}, workspace, locked);
  if (!lock) {
    state.SkipWithError(lock.error().message.c_str());
    return;
  }
  const animkit::bench::KdlModel model = animkit::bench::kdl_model(w->bvh, w->skeleton);
  std::array<KDL::Chain, 2> chains;
  for (int leg = 0; leg < 2; ++leg) {
    const animkit::LegJoints& l = w->legs[static_cast<std::size_t>(leg)];
    const int base = w->skeleton.parents()[static_cast<std::size_t>(l.hip)];
    const std::string ankle = w->skeleton.names()[static_cast<std::size_t>(l.ankle)] + "_offset";
    if (!model.tree.getChain(model.tips[static_cast<std::size_t>(base)], ankle,
                             chains[static_cast<std::size_t>(leg)])) {
      state.SkipWithError("no KDL chain for a leg");
      return;
    }
  }
  std::vector<KdlLegSolve> solves;
  animkit::SkeletonPose pose = animkit::skeleton_rest_pose(w->skeleton);
  for (int f = 0; f < w->motion.frame_count(); ++f) {
    w->motion.read_frame(f, pose);
    animkit::skeleton_forward_kinematics(w->skeleton, pose);
    const KDL::JntArray all = animkit::bench::kdl_frame(w->bvh, model, f);
    for (int leg = 0; leg < 2; ++leg) {
      const auto k = static_cast<std::size_t>(f * 2 + leg);
      if (lock->ankles_after[k] == lock->ankles_before[k]) continue;  // frame left as captured
      const animkit::LegJoints& l = w->legs[static_cast<std::size_t>(leg)];
      const auto base =
          static_cast<std::size_t>(w->skeleton.parents()[static_cast<std::size_t>(l.hip)]);
      KdlLegSolve solve{leg,
                        kdl(pose.global_rotations[base].conjugate() *
                            (lock->ankles_after[k] - pose.global_positions[base])),
                        KDL::JntArray(chains[static_cast<std::size_t>(leg)].getNrOfJoints())};
      unsigned q = 0;
      for (const int j : {l.hip, l.knee}) {
        for (int c = 0; c < 3 && q < solve.start.rows(); ++c) {
          solve.start(q++) =
              all(static_cast<unsigned>(model.first_q[static_cast<std::size_t>(j)] + c));
        }
      }
      // Both models must be one leg: KDL's FK of the captured angles is the captured ankle.
      KDL::Frame captured;
      KDL::ChainFkSolverPos_recursive(chains[static_cast<std::size_t>(leg)])
          .JntToCart(solve.start, captured);
      const Vec3 ankle =
          pose.global_rotations[base].conjugate() *
          (pose.global_positions[static_cast<std::size_t>(l.ankle)] - pose.global_positions[base]);
      if ((captured.p - kdl(ankle)).Norm() > 1e-9) {
        state.SkipWithError("KDL's leg does not match animkit's");
        return;
      }
      solves.push_back(solve);
    }
  }
  Eigen::Matrix<double, 6, 1> position_only;
  position_only << 1, 1, 1, 0, 0, 0;
  KDL::ChainIkSolverPos_LMA left(chains[0], position_only, 1e-5, 500, 1e-15);
  KDL::ChainIkSolverPos_LMA right(chains[1], position_only, 1e-5, 500, 1e-15);
  std::array<KDL::ChainFkSolverPos_recursive, 2> fk{KDL::ChainFkSolverPos_recursive(chains[0]),
                                                    KDL::ChainFkSolverPos_recursive(chains[1])};
  KDL::JntArray result(chains[0].getNrOfJoints());
  int converged = 0;
  for (auto _ : state) {
    converged = 0;
    for (const KdlLegSolve& s : solves) {
      KDL::ChainIkSolverPos_LMA& solver = s.leg == 0 ? left : right;
      const int status = solver.CartToJnt(s.start, KDL::Frame(s.target), result);
      KDL::Frame reached;
      fk[static_cast<std::size_t>(s.leg)].JntToCart(result, reached);
      converged += status >= 0 && (reached.p - s.target).Norm() <= 1e-4;
    }
    benchmark::DoNotOptimize(result);
  }
  state.counters["solves"] = static_cast<double>(solves.size());
  state.counters["converged"] =
      solves.empty() ? 0.0 : static_cast<double>(converged) / static_cast<double>(solves.size());
}

BENCHMARK(BM_FootLockWalk)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FootLockWalkColdWorkspace)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FootLockTargetsKdl)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  animkit::bench::RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratio("BM_FootLockTargetsKdl", "BM_FootLockWalk", "time",
                       "KDL LMA leg solves / animkit whole lock, time per clip");
  benchmark::Shutdown();
  return 0;
}
