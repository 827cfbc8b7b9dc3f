#include "animkit/trajectory/stroke_cover.h"

#include <algorithm>
#include <array>
#include <limits>

namespace animkit {

namespace {

// The nodes of each connected piece (pieces with at least one edge), found once.
std::vector<std::vector<int>> pieces_of(const SkeletonGraph& g,
                                        const std::vector<std::vector<int>>& incident) {
  std::vector<std::vector<int>> pieces;
  std::vector<char> seen(g.nodes.size(), 0);
  for (std::size_t s = 0; s < g.nodes.size(); ++s) {
    if (seen[s] || incident[s].empty()) continue;
    pieces.emplace_back();
    std::vector<int> stack{static_cast<int>(s)};
    seen[s] = 1;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      pieces.back().push_back(v);
      for (int e : incident[v]) {
        for (int u : {g.edges[e].a, g.edges[e].b}) {
          if (!seen[u]) {
            seen[u] = 1;
            stack.push_back(u);
          }
        }
      }
    }
  }
  return pieces;
}

}  // namespace

Strokes cover_with_strokes(const SkeletonGraph& g) {
  Strokes strokes;
  // Edge ids at each node (a loop appears twice); pen-up edges pairing odd nodes are appended
  // per piece, with ids from real_edges on.
  const int real_edges = static_cast<int>(g.edges.size());
  std::vector<std::vector<int>> incident(g.nodes.size());
  for (int e = 0; e < real_edges; ++e) {
    incident[g.edges[e].a].push_back(e);
    incident[g.edges[e].b].push_back(e);
  }
  for (std::size_t v = 0; v < g.nodes.size(); ++v) {
    if (g.nodes[v].dot) strokes.push_back({g.nodes[v].position});
  }
  std::vector<std::array<int, 2>> ends;
  for (const auto& e : g.edges) ends.push_back({e.a, e.b});
  std::vector<char> used(ends.size(), 0);
  std::vector<std::size_t> cursor(g.nodes.size(), 0);
  for (const std::vector<int>& piece : pieces_of(g, incident)) {
    // Odd nodes, paired greedily by distance with pen-up edges.
    std::vector<int> odd;
    for (int v : piece) {
      if (incident[v].size() % 2 == 1) odd.push_back(v);
    }
    std::vector<int> pen_up_edges;
    std::vector<char> paired(odd.size(), 0);
    for (std::size_t i = 0; i < odd.size(); ++i) {
      if (paired[i]) continue;
      std::size_t best = i;
      double best_distance = std::numeric_limits<double>::infinity();
      for (std::size_t j = i + 1; j < odd.size(); ++j) {
        const double d = (g.nodes[odd[i]].position - g.nodes[odd[j]].position).norm();
        if (!paired[j] && d < best_distance) {
          best = j;
          best_distance = d;
        }
      }
      paired[i] = paired[best] = 1;
      const int e = static_cast<int>(ends.size());
      ends.push_back({odd[i], odd[best]});
      used.push_back(0);
      pen_up_edges.push_back(e);
      incident[odd[i]].push_back(e);
      incident[odd[best]].push_back(e);
    }
    // Hierholzer's algorithm: an Euler circuit as (node reached, edge taken to reach it).
    const int start = odd.empty() ? piece.front() : odd.front();
    std::vector<std::pair<int, int>> stack{{start, -1}}, circuit;
    while (!stack.empty()) {
      const int v = stack.back().first;
      auto& c = cursor[v];
      while (c < incident[v].size() && used[incident[v][c]]) ++c;
      if (c == incident[v].size()) {
        circuit.push_back(stack.back());
        stack.pop_back();
        continue;
      }
      const int e = incident[v][c];
      used[e] = 1;
      stack.push_back({ends[e][0] == v ? ends[e][1] : ends[e][0], e});
    }
    std::reverse(circuit.begin(), circuit.end());
    // Split the circuit at pen-up edges into strokes of real edges.
    Strokes piece_strokes;
    Stroke current;
    for (std::size_t k = 1; k < circuit.size(); ++k) {
      const int e = circuit[k].second;
      if (e >= real_edges) {
        if (!current.empty()) piece_strokes.push_back(std::move(current));
        current.clear();
        continue;
      }
      const auto& px = g.edges[e].pixels;
      const bool forward = g.edges[e].a == circuit[k - 1].first;
      const long skip = current.empty() ? 0 : 1;  // the shared node is already there
      if (forward) {
        current.insert(current.end(), px.begin() + skip, px.end());
      } else {
        current.insert(current.end(), px.rbegin() + skip, px.rend());
      }
    }
    if (!current.empty()) {
      // The circuit wrapped: its last stroke continues into its first (no pen-up between).
      if (!piece_strokes.empty() && circuit.size() > 1 && circuit[1].second < real_edges) {
        current.insert(current.end(), piece_strokes.front().begin() + 1,
                       piece_strokes.front().end());
        piece_strokes.front() = std::move(current);
      } else {
        piece_strokes.push_back(std::move(current));
      }
    }
    strokes.insert(strokes.end(), piece_strokes.begin(), piece_strokes.end());
  }
  return strokes;
}

double travel_length(const Strokes& strokes) {
  double length = 0.0;
  for (std::size_t i = 1; i < strokes.size(); ++i) {
    if (!strokes[i - 1].empty() && !strokes[i].empty()) {
      length += (strokes[i].front() - strokes[i - 1].back()).norm();
    }
  }
  return length;
}

Strokes order_for_short_travel(Strokes strokes) {
  std::erase_if(strokes, [](const Stroke& s) { return s.empty(); });
  if (strokes.size() < 2) return strokes;
  Strokes ordered;
  ordered.reserve(strokes.size());
  std::vector<char> done(strokes.size(), 0);
  ordered.push_back(strokes[0]);
  done[0] = 1;
  for (std::size_t k = 1; k < strokes.size(); ++k) {
    const Point2 pen = ordered.back().back();
    std::size_t best = 0, best_index = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t s = 0; s < strokes.size(); ++s) {
      if (done[s]) continue;
      const Stroke& c = strokes[s];
      const bool closed = c.size() > 2 && (c.front() - c.back()).norm() < 1e-9;
      // Candidates: either end of an open stroke; any point of a closed one.
      const std::size_t last = c.size() - 1;
      for (std::size_t i = 0; i <= last; i += (closed ? 1 : std::max<std::size_t>(1, last))) {
        const double d = (c[i] - pen).norm();
        if (d < best_distance) {
          best_distance = d;
          best = s;
          best_index = i;
        }
      }
    }
    Stroke next = strokes[best];
    const bool closed = next.size() > 2 && (next.front() - next.back()).norm() < 1e-9;
    if (closed && best_index != 0) {
      // Start the loop at its nearest point: drop the repeated end, rotate, close again.
      next.pop_back();
      std::rotate(next.begin(), next.begin() + static_cast<long>(best_index), next.end());
      next.push_back(next.front());
    } else if (!closed && best_index != 0) {
      std::reverse(next.begin(), next.end());
    }
    done[best] = 1;
    ordered.push_back(std::move(next));
  }
  return ordered;
}

}  // namespace animkit
