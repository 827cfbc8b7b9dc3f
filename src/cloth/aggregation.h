#pragma once
// Aggregation of a graph's nodes for smoothed aggregation multigrid: the greedy three-phase
// scheme of Vanek, Mandel & Brezina, "Algebraic multigrid by smoothed aggregation for second
// and fourth order elliptic problems" (Computing 1996), section 4, which Tamstorf, Jones &
// McCormick use for cloth ("Smoothed aggregation multigrid for cloth simulation", SIGGRAPH
// Asia 2015). It reads only the graph, so it runs once per model: the cloth's connectivity
// never changes.
#include <vector>

namespace animkit {

struct Aggregates {
  std::vector<int> of_node;  ///< aggregate of each node, or -1 for an excluded node
  int count = 0;
};

/// Aggregates the nodes of the graph given by adjacency lists in compressed form (node i's
/// neighbours are column[row_start[i] .. row_start[i + 1]); a node may list itself, which is
/// ignored). Excluded nodes (pinned particles: identity rows, no unknowns) join no aggregate
/// and connect nothing. Deterministic: nodes are visited in index order.
Aggregates aggregate_graph(const std::vector<int>& row_start, const std::vector<int>& column,
                           const std::vector<char>& excluded);

}  // namespace animkit
