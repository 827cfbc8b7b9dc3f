// Foot locking of the whole CMU walk 131_01 (994 frames, both feet): detection, the two-bone
// solves, and the metrics, as `animkit footlock` runs them, with the workspace reused between
// runs (the CLI's case is one run: see BM_FootLockWalkColdWorkspace). The target is 50 ms per
// clip. The clip is read once, outside the timing.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>

#include "animkit/io/bvh.h"
#include "animkit/io/bvh_motion.h"
#include "animkit/kinematics/foot_lock.h"

namespace {

struct Walk {
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
    return Walk{*skeleton, *legs, animkit::motion_from_bvh(*clip)};
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

BENCHMARK(BM_FootLockWalk)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FootLockWalkColdWorkspace)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
