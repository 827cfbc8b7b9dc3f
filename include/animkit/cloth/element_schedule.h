#pragma once
// An order for adding the springs' (or bends') terms into their particles that threads can
// share without atomics and that gives the same bits for any thread count.
//
// The elements are sorted by their highest particle index and cut into kSegments segments of
// consecutive elements. On a cloth whose particles are numbered row by row (any grid, most
// meshes after a bandwidth-reducing ordering), a segment touches a narrow band of particles,
// so segments 0, 2, 4, ... touch disjoint particles and can run at once, then 1, 3, 5, ....
// Each particle then receives its terms in one fixed order (the even segments', then the odd
// ones'), whichever thread runs which segment. When the bands of same-parity segments
// overlap (a mesh with scattered numbering) the segments run one after another, in the same
// order, on one thread.
#include <array>
#include <vector>

namespace animkit {

/// A thread-count-independent order of elements (springs or bends) for accumulating their
/// terms into particles (see the comment at the top of element_schedule.h).
struct ElementSchedule {
  static constexpr int kSegments = 16;  ///< segments the sorted elements are cut into

  std::vector<int> order;          ///< element indices, by highest particle (stable)
  std::vector<int> segment_start;  ///< kSegments + 1 offsets into `order`
  bool parallel = false;           ///< same-parity segments touch disjoint particles

  ElementSchedule() = default;
  /// `elements[e]` lists element e's particles (indices below particle_count; the first one
  /// used, -1 marks an unused slot).
  template <class Elements>
  ElementSchedule(const Elements& elements, int particle_count);

  /// Number of elements scheduled.
  int size() const { return static_cast<int>(order.size()); }

 private:
  void build(const std::vector<int>& lowest, const std::vector<int>& highest, int particle_count);
};

template <class Elements>
ElementSchedule::ElementSchedule(const Elements& elements, int particle_count) {
  std::vector<int> lowest, highest;
  lowest.reserve(elements.size());
  highest.reserve(elements.size());
  for (const auto& element : elements) {
    int lo = element[0], hi = element[0];
    for (int p : element) {
      if (p < 0) continue;  // an unused slot (a three-particle bend)
      lo = p < lo ? p : lo;
      hi = p > hi ? p : hi;
    }
    lowest.push_back(lo);
    highest.push_back(hi);
  }
  build(lowest, highest, particle_count);
}

}  // namespace animkit
