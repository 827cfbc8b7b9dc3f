#include "animkit/cloth/element_schedule.h"

#include <algorithm>
#include <numeric>

namespace animkit {

void ElementSchedule::build(const std::vector<int>& lowest, const std::vector<int>& highest,
                            int particle_count) {
  const int count = static_cast<int>(highest.size());
  // Counting sort by highest particle: stable, so a grid's springs (listed at their higher
  // particle) keep their order.
  std::vector<int> start(static_cast<std::size_t>(particle_count) + 1, 0);
  for (int h : highest) ++start[static_cast<std::size_t>(h) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  order.resize(static_cast<std::size_t>(count));
  for (int e = 0; e < count; ++e) order[static_cast<std::size_t>(start[highest[e]]++)] = e;

  segment_start.resize(kSegments + 1);
  for (int s = 0; s <= kSegments; ++s)
    segment_start[static_cast<std::size_t>(s)] =
        static_cast<int>(static_cast<long>(count) * s / kSegments);
  // Each segment's band of particles [lo, hi]; same-parity bands must not overlap. Sorted by
  // highest particle, the bands' upper ends increase, so comparing segment s with s + 2 is
  // not enough only when a low end reaches further back: check every same-parity pair.
  std::array<int, kSegments> lo{}, hi{};
  for (int s = 0; s < kSegments; ++s) {
    lo[s] = particle_count;
    hi[s] = -1;
    for (int k = segment_start[s]; k < segment_start[s + 1]; ++k) {
      const int e = order[static_cast<std::size_t>(k)];
      lo[s] = std::min(lo[s], lowest[e]);
      hi[s] = std::max(hi[s], highest[e]);
    }
  }
  parallel = true;
  for (int s = 0; s < kSegments && parallel; ++s) {
    for (int t = s + 2; t < kSegments; t += 2) {
      const bool empty = hi[s] < lo[s] || hi[t] < lo[t];
      if (!empty && lo[t] <= hi[s] && lo[s] <= hi[t]) {
        parallel = false;
        break;
      }
    }
  }
}

}  // namespace animkit
