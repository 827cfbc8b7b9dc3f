#include "animkit/collision/box_tree.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

namespace animkit {
namespace {

std::vector<AlignedBox> random_boxes(int count, double spread, double size, std::mt19937& rng) {
  std::uniform_real_distribution<double> where(-spread, spread), extent(0.0, size);
  std::vector<AlignedBox> boxes;
  for (int i = 0; i < count; ++i) {
    const Vec3 lo(where(rng), where(rng), where(rng));
    boxes.push_back({lo, lo + Vec3(extent(rng), extent(rng), extent(rng))});
  }
  return boxes;
}

// The boxes each query finds, sorted, against testing every box. Returns how many queries
// found any.
int expect_same_as_every_box(const BoxTree& tree, const std::vector<AlignedBox>& boxes,
                              const std::vector<AlignedBox>& queries) {
  int found_any = 0;
  for (const AlignedBox& query : queries) {
    std::vector<int> found, expected;
    tree.overlapping(query, boxes.data(), [&](int i) { found.push_back(i); });
    for (int i = 0; i < static_cast<int>(boxes.size()); ++i)
      if (boxes_overlap(boxes[static_cast<std::size_t>(i)], query)) expected.push_back(i);
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, expected);
    found_any += found.empty() ? 0 : 1;
  }
  return found_any;
}

TEST(BoxTree, FindsExactlyTheOverlappingBoxes) {
  std::mt19937 rng(3);
  for (const int count : {0, 1, 3, 4, 5, 17, 1000}) {
    const std::vector<AlignedBox> boxes = random_boxes(count, 1.0, 0.2, rng);
    BoxTree tree;
    tree.build(boxes.data(), count);
    tree.refit(boxes.data());
    EXPECT_EQ(tree.size(), count);
    const int found_any = expect_same_as_every_box(tree, boxes, random_boxes(200, 1.0, 0.3, rng));
    if (count >= 1000) {
      EXPECT_GT(found_any, 100);  // the queries do meet boxes
    }
  }
}

TEST(BoxTree, TouchingBoxesOverlap) {
  const std::vector<AlignedBox> boxes = {{Vec3(0, 0, 0), Vec3(1, 1, 1)}};
  BoxTree tree;
  tree.build(boxes.data(), 1);
  tree.refit(boxes.data());
  int found = 0;
  tree.overlapping({Vec3(1, 1, 1), Vec3(2, 2, 2)}, boxes.data(), [&](int) { ++found; });
  EXPECT_EQ(found, 1);
  tree.overlapping({Vec3(1, 1, 1.0000001), Vec3(2, 2, 2)}, boxes.data(), [&](int) { ++found; });
  EXPECT_EQ(found, 1);
}

// Moved boxes, refitted without a rebuild: still exactly the overlapping ones. A rigid move
// leaves the tree as tight as built; boxes scattered apart loosen it, which refit() reports.
TEST(BoxTree, RefittedAfterAMoveStaysExact) {
  std::mt19937 rng(4);
  std::vector<AlignedBox> boxes = random_boxes(500, 0.5, 0.05, rng);
  BoxTree tree;
  tree.build(boxes.data(), 500);
  const double built = tree.refit(boxes.data());
  for (AlignedBox& box : boxes) {
    box.lo += Vec3(3.0, -1.0, 0.5);
    box.hi += Vec3(3.0, -1.0, 0.5);
  }
  EXPECT_NEAR(tree.refit(boxes.data()), built, 1e-9 * built);
  std::vector<AlignedBox> queries = random_boxes(200, 0.5, 0.2, rng);
  for (AlignedBox& query : queries) {
    query.lo += Vec3(3.0, -1.0, 0.5);
    query.hi += Vec3(3.0, -1.0, 0.5);
  }
  EXPECT_GT(expect_same_as_every_box(tree, boxes, queries), 100);
  std::shuffle(boxes.begin(), boxes.end(), rng);  // the same boxes, other indices
  EXPECT_GT(tree.refit(boxes.data()), 2.0 * built);
  EXPECT_GT(expect_same_as_every_box(tree, boxes, queries), 100);
}

}  // namespace
}  // namespace animkit
