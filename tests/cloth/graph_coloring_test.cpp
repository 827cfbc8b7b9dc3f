#include "animkit/cloth/graph_coloring.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "animkit/cloth/grid_cloth.h"

namespace animkit {
namespace {

// Every line of the grid along i and along j, as bends over consecutive triples.
ClothDesc grid_with_bends(int cells) {
  ClothDesc desc = make_grid_cloth({.cells = cells});
  for (int i = 0; i <= cells; ++i) {
    for (int j = 0; j + 2 <= cells; ++j) {
      desc.bends.push_back(line_bend(grid_index(cells, i, j), grid_index(cells, i, j + 1),
                                     grid_index(cells, i, j + 2), 10.0));
      desc.bends.push_back(line_bend(grid_index(cells, j, i), grid_index(cells, j + 1, i),
                                     grid_index(cells, j + 2, i), 10.0));
    }
  }
  // One along a diagonal, whose outer pair no spring joins.
  desc.bends.push_back(
      line_bend(grid_index(cells, 0, 0), grid_index(cells, 1, 1), grid_index(cells, 2, 2), 5.0));
  return desc;
}

TEST(GraphColoring, SmallGraphsGetTheGreedyColours) {
  const std::vector<std::array<int, 2>> triangle{{0, 1}, {1, 2}, {2, 0}};
  const GraphColoring t = greedy_coloring(3, triangle);
  EXPECT_EQ(t.color, (std::vector<int>{0, 1, 2}));
  EXPECT_TRUE(is_valid_coloring(t, triangle));

  const std::vector<std::array<int, 2>> path{{0, 1}, {1, 2}, {2, 3}, {1, 2}};  // a repeated edge
  const GraphColoring p = greedy_coloring(5, path);  // vertex 4 is isolated
  EXPECT_EQ(p.color, (std::vector<int>{0, 1, 0, 1, 0}));
  EXPECT_EQ(p.color_count(), 2);
  EXPECT_EQ(p.vertices, (std::vector<int>{0, 2, 4, 1, 3}));
  EXPECT_EQ(p.offsets, (std::vector<int>{0, 3, 5}));
  EXPECT_TRUE(is_valid_coloring(p, path));

  const GraphColoring empty = greedy_coloring(0, {});
  EXPECT_EQ(empty.color_count(), 0);
}

TEST(GraphColoring, InvalidColouringsAreDetected) {
  const std::vector<std::array<int, 2>> edge{{0, 1}};
  GraphColoring c = greedy_coloring(2, edge);
  ASSERT_TRUE(is_valid_coloring(c, edge));
  c.color = {0, 0};
  EXPECT_FALSE(is_valid_coloring(c, edge));
}

TEST(GraphColoring, ClothColouringIsValidAndDeterministic) {
  for (const ClothDesc& desc :
       {make_grid_cloth(), make_grid_cloth({.cells = 30}), grid_with_bends(8)}) {
    const auto built = build_cloth(desc);
    ASSERT_TRUE(built) << built.error().message;
    const ClothModel& model = built->model;
    const auto edges = cloth_conflict_edges(model);
    const GraphColoring coloring = color_cloth_particles(model);
    EXPECT_TRUE(is_valid_coloring(coloring, edges));
    // No two particles of one colour share a spring or a bend, checked element by element.
    for (const auto& [a, b] : model.springs) EXPECT_NE(coloring.color[a], coloring.color[b]);
    for (const auto& bend : model.bends) {
      const int a = bend[0], b = bend[1], c = bend[2];
      EXPECT_NE(coloring.color[a], coloring.color[b]);
      EXPECT_NE(coloring.color[b], coloring.color[c]);
      EXPECT_NE(coloring.color[a], coloring.color[c]);
    }
    // Greedy: at most max degree + 1 colours (a grid particle has 12 spring neighbours).
    std::vector<int> degree(static_cast<std::size_t>(model.particle_count()), 0);
    for (const auto& [a, b] : edges) {
      ++degree[static_cast<std::size_t>(a)];
      ++degree[static_cast<std::size_t>(b)];
    }
    EXPECT_LE(coloring.color_count(), *std::max_element(degree.begin(), degree.end()) + 1);
    const GraphColoring again = color_cloth_particles(model);
    EXPECT_EQ(again.color, coloring.color);
    EXPECT_EQ(again.vertices, coloring.vertices);
    EXPECT_EQ(again.offsets, coloring.offsets);
  }
}

}  // namespace
}  // namespace animkit
