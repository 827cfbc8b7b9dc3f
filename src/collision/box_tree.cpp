#include "animkit/collision/box_tree.h"

#include <algorithm>

namespace animkit {

namespace {

constexpr int kLeafSize = 4;

AlignedBox united(const AlignedBox& a, const AlignedBox& b) {
  return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
}

// The union of boxes[order[first]], ..., boxes[order[first + count - 1]], count >= 1.
AlignedBox union_of(const AlignedBox* boxes, const std::vector<int>& order, int first,
                    int count) {
  AlignedBox box = boxes[order[static_cast<std::size_t>(first)]];
  for (int k = first + 1; k < first + count; ++k)
    box = united(box, boxes[order[static_cast<std::size_t>(k)]]);
  return box;
}

double surface_area(const AlignedBox& box) {
  const Vec3 d = box.hi - box.lo;
  return 2.0 * (d.x() * d.y() + d.y() * d.z() + d.z() * d.x());
}

}  // namespace

void BoxTree::build(const AlignedBox* boxes, int count) {
  nodes_.clear();
  order_.resize(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) order_[static_cast<std::size_t>(i)] = i;
  if (count == 0) return;
  // Median splits of more than kLeafSize boxes leave at least 2 in every leaf: at most
  // count / 2 leaves, so fewer than `count` nodes.
  nodes_.reserve(static_cast<std::size_t>(count));
  build_node(boxes, 0, count);
}

int BoxTree::build_node(const AlignedBox* boxes, int begin, int end) {
  const int index = static_cast<int>(nodes_.size());
  nodes_.emplace_back();
  const AlignedBox box = union_of(boxes, order_, begin, end - begin);
  nodes_[static_cast<std::size_t>(index)].box = box;
  if (end - begin <= kLeafSize) {
    nodes_[static_cast<std::size_t>(index)].first = begin;
    nodes_[static_cast<std::size_t>(index)].count = end - begin;
    return index;
  }
  int axis = 0;
  (box.hi - box.lo).maxCoeff(&axis);
  const int middle = begin + (end - begin) / 2;
  // Ties broken by index, so the shape depends on the boxes alone.
  const auto centre = [&](int i) { return boxes[i].lo[axis] + boxes[i].hi[axis]; };
  std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                   [&](int a, int b) {
                     const double ca = centre(a), cb = centre(b);
                     return ca < cb || (ca == cb && a < b);
                   });
  const int left = build_node(boxes, begin, middle);
  const int right = build_node(boxes, middle, end);
  nodes_[static_cast<std::size_t>(index)].first = left;
  nodes_[static_cast<std::size_t>(index)].right = right;
  return index;
}

double BoxTree::refit(const AlignedBox* boxes) {
  double inner_area = 0.0;
  // Children follow their parent in pre-order, so a reverse pass meets them first.
  for (auto node = nodes_.rbegin(); node != nodes_.rend(); ++node) {
    if (node->count > 0) {
      node->box = union_of(boxes, order_, node->first, node->count);
    } else {
      node->box = united(nodes_[static_cast<std::size_t>(node->first)].box,
                         nodes_[static_cast<std::size_t>(node->right)].box);
      inner_area += surface_area(node->box);
    }
  }
  return inner_area;
}

}  // namespace animkit
