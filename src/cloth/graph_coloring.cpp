#include "animkit/cloth/graph_coloring.h"

#include <algorithm>
#include <cassert>

#include "animkit/cloth/bend_energy.h"

namespace animkit {

GraphColoring greedy_coloring(int vertex_count, std::span<const std::array<int, 2>> edges) {
  const auto n = static_cast<std::size_t>(vertex_count);
  // Adjacency in compressed rows (both directions of every edge).
  std::vector<int> start(n + 1, 0);
  for (const auto& [a, b] : edges) {
    assert(a != b && a >= 0 && b >= 0 && a < vertex_count && b < vertex_count);
    ++start[static_cast<std::size_t>(a) + 1];
    ++start[static_cast<std::size_t>(b) + 1];
  }
  for (std::size_t i = 0; i < n; ++i) start[i + 1] += start[i];
  std::vector<int> neighbors(static_cast<std::size_t>(start[n]));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (const auto& [a, b] : edges) {
    neighbors[static_cast<std::size_t>(fill[static_cast<std::size_t>(a)]++)] = b;
    neighbors[static_cast<std::size_t>(fill[static_cast<std::size_t>(b)]++)] = a;
  }

  GraphColoring coloring;
  coloring.color.assign(n, -1);
  // taken[c] == v: colour c is used by a neighbour of v (stamped, so never cleared).
  std::vector<int> taken;
  int colors = 0;
  for (int v = 0; v < vertex_count; ++v) {
    const auto vi = static_cast<std::size_t>(v);
    for (int e = start[vi]; e < start[vi + 1]; ++e) {
      const int c =
          coloring.color[static_cast<std::size_t>(neighbors[static_cast<std::size_t>(e)])];
      if (c >= 0) taken[static_cast<std::size_t>(c)] = v;
    }
    int c = 0;
    while (c < colors && taken[static_cast<std::size_t>(c)] == v) ++c;
    if (c == colors) {
      ++colors;
      taken.push_back(-1);
    }
    coloring.color[vi] = c;
  }

  // Group by colour (a counting sort keeps increasing vertex order within a colour).
  coloring.offsets.assign(static_cast<std::size_t>(colors) + 1, 0);
  for (int c : coloring.color) ++coloring.offsets[static_cast<std::size_t>(c) + 1];
  for (int c = 0; c < colors; ++c) {
    coloring.offsets[static_cast<std::size_t>(c) + 1] +=
        coloring.offsets[static_cast<std::size_t>(c)];
  }
  coloring.vertices.resize(n);
  std::vector<int> next(coloring.offsets.begin(), coloring.offsets.end() - 1);
  for (int v = 0; v < vertex_count; ++v) {
    const auto c = static_cast<std::size_t>(coloring.color[static_cast<std::size_t>(v)]);
    coloring.vertices[static_cast<std::size_t>(next[c]++)] = v;
  }
  return coloring;
}

std::vector<std::array<int, 2>> cloth_conflict_edges(const ClothModel& model) {
  std::vector<std::array<int, 2>> edges(model.springs.begin(), model.springs.end());
  for (const auto& bend : model.bends) {
    for (const auto& [i, j] : kBendPairs) {
      if (bend[i] >= 0 && bend[j] >= 0) edges.push_back({bend[i], bend[j]});
    }
  }
  return edges;
}

GraphColoring color_cloth_particles(const ClothModel& model) {
  return greedy_coloring(model.particle_count(), cloth_conflict_edges(model));
}

bool is_valid_coloring(const GraphColoring& coloring, std::span<const std::array<int, 2>> edges) {
  const auto n = coloring.color.size();
  if (coloring.vertices.size() != n || coloring.offsets.empty() || coloring.offsets.front() != 0 ||
      coloring.offsets.back() != static_cast<int>(n)) {
    return false;
  }
  std::vector<char> seen(n, 0);
  for (int c = 0; c < coloring.color_count(); ++c) {
    for (int v : coloring.members(c)) {
      if (v < 0 || static_cast<std::size_t>(v) >= n || seen[static_cast<std::size_t>(v)] ||
          coloring.color[static_cast<std::size_t>(v)] != c) {
        return false;
      }
      seen[static_cast<std::size_t>(v)] = 1;
    }
  }
  return std::all_of(edges.begin(), edges.end(), [&](const std::array<int, 2>& e) {
    return coloring.color[static_cast<std::size_t>(e[0])] !=
           coloring.color[static_cast<std::size_t>(e[1])];
  });
}

}  // namespace animkit
