#pragma once
// The reference quality mode (IPC's settings, use_reference_contact_settings) stepped from
// every state a run reaches, to tell how far each of the run's steps ends from the reference's
// step from the same state (docs/contact.md). The drape and scenes benchmarks share it; its
// steps are kept out of the benchmark's timing.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <vector>

#include "animkit/cloth/cloth_world.h"

namespace animkit::bench {

/// The largest distance between the same particle of two states, m.
inline double largest_distance(const ClothState& a, const ClothState& b) {
  const Eigen::VectorXd difference = a.positions - b.positions;
  return difference.reshaped(3, difference.size() / 3).colwise().norm().maxCoeff();
}

class ReferenceSteps {
 public:
  /// A world of `desc` with IPC's settings.
  explicit ReferenceSteps(const ClothWorldDesc& desc) : world_(build_reference(desc)) {}

  /// Steps the reference by `dt` from `from`, the run's state before its own step, with the
  /// benchmark's timing paused.
  void step_from(benchmark::State& timing, const ClothState& from, double dt) {
    timing.PauseTiming();
    (void)world_.simulator.set_state(from);
    (void)world_.simulator.step(dt);
    timing.ResumeTiming();
  }

  /// After the run's step to `reached`: how far it ended from the reference's step, m.
  double compare(const ClothState& reached) {
    apart_.push_back(largest_distance(reached, world_.simulator.state()));
    return apart_.back();
  }

  /// Counters apart_mm_median and apart_mm_max over every compared step, mm.
  void report(benchmark::State& state) const {
    std::vector<double> sorted = apart_;
    std::sort(sorted.begin(), sorted.end());
    state.counters["apart_mm_median"] = 1e3 * sorted[sorted.size() / 2];
    state.counters["apart_mm_max"] = 1e3 * sorted.back();
  }

 private:
  static ClothWorld build_reference(ClothWorldDesc desc) {
    use_reference_contact_settings(desc);
    return *build_cloth_world(desc);
  }

  ClothWorld world_;
  std::vector<double> apart_;  ///< per compared step, m
};

}  // namespace animkit::bench
