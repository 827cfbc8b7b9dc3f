#pragma once
// Per particle, the springs and bends that touch it, in increasing element order (compressed
// rows). Parallel loops gather each particle's terms over these lists instead of scattering
// each element's terms to its particles: every output is then written by one thread, summed
// in a fixed order (src/core/parallel.h), so results do not depend on the thread count.
#include <vector>

#include "animkit/cloth/cloth_model.h"

namespace animkit {

struct ParticleIncidence {
  /// Particle i's springs are spring_entry[spring_start[i] .. spring_start[i + 1]), each
  /// 2 s + e: spring s with i at its end e (0: a, 1: b).
  std::vector<int> spring_start, spring_entry;
  /// Particle i's bends are bend_entry[bend_start[i] .. bend_start[i + 1]), each 3 k + j:
  /// bend k with i in slot j (0: a, 1: b, 2: c).
  std::vector<int> bend_start, bend_entry;

  explicit ParticleIncidence(const ClothModel& model);
};

}  // namespace animkit
