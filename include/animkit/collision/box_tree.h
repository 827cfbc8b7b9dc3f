#pragma once
// A bounding volume hierarchy over a list of axis-aligned boxes: a binary tree whose leaves hold
// up to four boxes and whose nodes hold the union of their children's boxes, split at the median
// of the boxes' centres along the node's longest axis (Ericson, "Real-Time Collision Detection",
// 2005, section 6.2). Built once for a list; when the boxes move, refit() recomputes the nodes'
// boxes bottom-up in linear time and keeps the tree's shape, which stays tight while the boxes
// move together (a rigid collider). overlapping() reports every box that overlaps a query box,
// testing each leaf box exactly as a pairwise test would, so a query finds the same boxes as
// testing them all.
#include <array>
#include <vector>

#include "animkit/core/types.h"

namespace animkit {

/// An axis-aligned box, world space.
struct AlignedBox {
  Vec3 lo;  ///< lower corner (componentwise minimum)
  Vec3 hi;  ///< upper corner (componentwise maximum)
};

/// True when the boxes share a point (touching counts as overlapping).
inline bool boxes_overlap(const AlignedBox& a, const AlignedBox& b) {
  return !((a.lo.array() > b.hi.array()).any() || (b.lo.array() > a.hi.array()).any());
}

/// The hierarchy over `count` boxes; indices are positions in the list it was built from.
class BoxTree {
 public:
  /// A new tree over boxes[0, count).
  void build(const AlignedBox* boxes, int count);
  /// The same boxes moved (as many as built): every node's box recomputed. Returns the sum of
  /// the inner nodes' box surface areas, a measure of how loose the tree's shape has become.
  double refit(const AlignedBox* boxes);
  /// The number of boxes the tree holds.
  int size() const { return static_cast<int>(order_.size()); }

  /// Calls visit(i) for each box i (as last built or refitted) that overlaps `query`.
  template <class Visit>
  void overlapping(const AlignedBox& query, const AlignedBox* boxes, Visit&& visit) const {
    if (nodes_.empty()) return;
    std::array<int, 64> stack;  // depth <= log2(count / 4) + 1 with median splits
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[static_cast<std::size_t>(stack[--top])];
      if (!boxes_overlap(node.box, query)) continue;
      if (node.count > 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const int i = order_[static_cast<std::size_t>(k)];
          if (boxes_overlap(boxes[i], query)) visit(i);
        }
        continue;
      }
      stack[top++] = node.right;
      stack[top++] = node.first;  // the left child: the next node in pre-order
    }
  }

 private:
  // Pre-order: a node's children follow it. An inner node has count 0, its left child at
  // `first` and its right child at `right`; a leaf holds order_[first, first + count).
  struct Node {
    AlignedBox box;
    int first = 0;
    int count = 0;
    int right = 0;
  };
  int build_node(const AlignedBox* boxes, int begin, int end);
  std::vector<Node> nodes_;
  std::vector<int> order_;
};

}  // namespace animkit
