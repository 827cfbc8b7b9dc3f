#include "aggregation.h"

#include <cassert>

namespace animkit {

Aggregates aggregate_graph(const std::vector<int>& row_start, const std::vector<int>& column,
                           const std::vector<char>& excluded) {
  const int n = static_cast<int>(excluded.size());
  assert(static_cast<int>(row_start.size()) == n + 1);
  Aggregates result;
  std::vector<int>& agg = result.of_node;
  agg.assign(n, -1);
  const auto neighbours = [&](int i, auto&& visit) {
    for (int k = row_start[i]; k < row_start[i + 1]; ++k) {
      const int j = column[k];
      if (j != i && !excluded[j]) visit(j);
    }
  };
  // Phase 1: a node whose whole neighbourhood is still free becomes a root; the aggregate is
  // the root and its neighbours (disjoint neighbourhoods, each about one stencil wide).
  for (int i = 0; i < n; ++i) {
    if (excluded[i] || agg[i] >= 0) continue;
    bool free = true;
    neighbours(i, [&](int j) { free = free && agg[j] < 0; });
    if (!free) continue;
    agg[i] = result.count;
    neighbours(i, [&](int j) { agg[j] = result.count; });
    ++result.count;
  }
  // Phase 2: a left-over node joins the phase-1 aggregate it is connected to most often
  // (first such aggregate in index order on ties), so aggregates stay compact.
  const std::vector<int> phase1 = agg;
  std::vector<int> votes(static_cast<std::size_t>(result.count), 0);
  for (int i = 0; i < n; ++i) {
    if (excluded[i] || agg[i] >= 0) continue;
    int best = -1;
    neighbours(i, [&](int j) {
      if (phase1[j] >= 0) ++votes[phase1[j]];
    });
    neighbours(i, [&](int j) {
      const int a = phase1[j];
      if (a >= 0 && (best < 0 || votes[a] > votes[best] || (votes[a] == votes[best] && a < best)))
        best = a;
    });
    neighbours(i, [&](int j) {
      if (phase1[j] >= 0) votes[phase1[j]] = 0;
    });
    agg[i] = best;
  }
  // Phase 3: nodes with no aggregated neighbour (islands, e.g. cut off by pinned nodes) form
  // aggregates of their own with their still-free neighbours.
  for (int i = 0; i < n; ++i) {
    if (excluded[i] || agg[i] >= 0) continue;
    agg[i] = result.count;
    neighbours(i, [&](int j) {
      if (agg[j] < 0) agg[j] = result.count;
    });
    ++result.count;
  }
  return result;
}

}  // namespace animkit
