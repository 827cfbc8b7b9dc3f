#include "animkit/trajectory/skeleton_strokes.h"

#include <algorithm>
#include <limits>
#include <map>

namespace animkit {

namespace {

// m-adjacent ink neighbours of (x, y): the 4-neighbours, and a diagonal one only when neither
// pixel between them is ink.
std::vector<int> m_neighbours(const BinaryImage& im, int x, int y) {
  std::vector<int> out;
  static constexpr int four[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  static constexpr int diagonal[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
  for (const auto& d : four) {
    if (im.get(x + d[0], y + d[1])) out.push_back((y + d[1]) * im.width + x + d[0]);
  }
  for (const auto& d : diagonal) {
    if (im.get(x + d[0], y + d[1]) && !im.get(x + d[0], y) && !im.get(x, y + d[1])) {
      out.push_back((y + d[1]) * im.width + x + d[0]);
    }
  }
  return out;
}

Point2 centre_of(int pixel, int width) {
  return Point2(pixel % width, pixel / width);
}

}  // namespace

SkeletonGraph skeleton_graph(const BinaryImage& im) {
  SkeletonGraph g;
  const int w = im.width;
  const std::size_t n = im.pixels.size();
  std::vector<std::vector<int>> adjacent(n);
  for (int y = 0; y < im.height; ++y) {
    for (int x = 0; x < w; ++x) {
      if (im.get(x, y)) adjacent[static_cast<std::size_t>(y) * w + x] = m_neighbours(im, x, y);
    }
  }
  // Node pixels: ends (one neighbour) and junctions (three or more); touching junction pixels
  // form one node.
  std::vector<int> node_of(n, -1);
  std::vector<std::vector<int>> node_pixels;
  for (std::size_t p = 0; p < n; ++p) {
    if (!im.pixels[p] || node_of[p] >= 0) continue;
    const std::size_t degree = adjacent[p].size();
    if (degree == 2 || degree == 0) continue;
    const int id = static_cast<int>(node_pixels.size());
    node_pixels.emplace_back();
    std::vector<int> stack{static_cast<int>(p)};
    node_of[p] = id;
    while (!stack.empty()) {
      const int q = stack.back();
      stack.pop_back();
      node_pixels[id].push_back(q);
      if (adjacent[q].size() < 3) continue;  // an end is a node on its own
      for (int r : adjacent[q]) {
        if (node_of[r] < 0 && adjacent[r].size() >= 3) {
          node_of[r] = id;
          stack.push_back(r);
        }
      }
    }
  }
  const auto add_node = [&](const std::vector<int>& pixels) {
    Point2 sum = Point2::Zero();
    for (int q : pixels) sum += centre_of(q, w);
    g.nodes.push_back({sum / static_cast<double>(pixels.size()), 0});
  };
  for (const auto& pixels : node_pixels) add_node(pixels);

  // Walks from node pixel `start` through its neighbour `first` along chain pixels to the
  // next node pixel, marking the chain visited.
  std::vector<char> visited(n, 0);
  std::map<std::pair<int, int>, bool> used_step;  // (node pixel, first chain pixel) taken
  const auto trace = [&](int start, int first) {
    std::vector<int> chain{start};
    int previous = start, current = first;
    while (node_of[current] < 0) {
      chain.push_back(current);
      visited[current] = 1;
      const auto& next = adjacent[current];
      const int step = next[0] == previous ? next[1] : next[0];
      if (step == start && node_of[start] < 0) break;  // a closed loop back to its start
      previous = current;
      current = step;
    }
    chain.push_back(current);
    return chain;
  };
  const auto add_edge = [&](const std::vector<int>& chain) {
    SkeletonGraph::Edge e;
    e.a = node_of[chain.front()];
    e.b = node_of[chain.back()];
    e.pixels.push_back(g.nodes[e.a].position);
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) e.pixels.push_back(centre_of(chain[i], w));
    e.pixels.push_back(g.nodes[e.b].position);
    ++g.nodes[e.a].degree;
    ++g.nodes[e.b].degree;
    g.edges.push_back(std::move(e));
  };
  for (std::size_t p = 0; p < n; ++p) {
    if (node_of[p] < 0) continue;
    for (int q : adjacent[p]) {
      if (node_of[q] == node_of[p]) continue;  // inside one junction
      if (used_step[{static_cast<int>(p), q}]) continue;
      const std::vector<int> chain = trace(static_cast<int>(p), q);
      // The same edge walked back from its other end must not be added again.
      used_step[{static_cast<int>(p), q}] = true;
      used_step[{chain.back(), chain[chain.size() - 2]}] = true;
      add_edge(chain);
    }
  }
  // Loops with no node (a ring): one node on the loop, one edge round it.
  for (std::size_t p = 0; p < n; ++p) {
    if (!im.pixels[p] || visited[p] || node_of[p] >= 0 || adjacent[p].size() != 2) continue;
    node_of[p] = static_cast<int>(g.nodes.size());
    add_node({static_cast<int>(p)});
    visited[p] = 1;
    add_edge(trace(static_cast<int>(p), adjacent[p][0]));
  }
  return g;
}

int prune_spurs(SkeletonGraph& g, double max_length) {
  const auto is_spur = [&](const SkeletonGraph::Edge& e) {
    const int da = g.nodes[e.a].degree, db = g.nodes[e.b].degree;
    return ((da == 1 && db >= 3) || (db == 1 && da >= 3)) && stroke_length(e.pixels) <= max_length;
  };
  // Decide on the degrees as thinning left them, so pruning one spur cannot turn its
  // junction's other branches into spurs.
  std::vector<char> spur(g.edges.size(), 0);
  for (std::size_t e = 0; e < g.edges.size(); ++e) spur[e] = is_spur(g.edges[e]) ? 1 : 0;
  std::vector<SkeletonGraph::Edge> kept;
  int removed = 0;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (spur[e]) {
      --g.nodes[g.edges[e].a].degree;
      --g.nodes[g.edges[e].b].degree;
      ++removed;
    } else {
      kept.push_back(std::move(g.edges[e]));
    }
  }
  g.edges = std::move(kept);
  return removed;
}

Strokes cover_with_strokes(const SkeletonGraph& g) {
  // Edge ids at each node (a loop appears twice), plus pen-up edges pairing odd nodes.
  const int real_edges = static_cast<int>(g.edges.size());
  std::vector<std::array<int, 2>> ends;
  for (const auto& e : g.edges) ends.push_back({e.a, e.b});
  // Odd nodes of each connected piece, paired greedily by distance.
  std::vector<int> piece(g.nodes.size(), -1);
  std::vector<std::vector<int>> incident(g.nodes.size());
  for (int e = 0; e < real_edges; ++e) {
    incident[ends[e][0]].push_back(e);
    incident[ends[e][1]].push_back(e);
  }
  int pieces = 0;
  for (std::size_t s = 0; s < g.nodes.size(); ++s) {
    if (piece[s] >= 0 || incident[s].empty()) continue;
    std::vector<int> stack{static_cast<int>(s)};
    piece[s] = pieces;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int e : incident[v]) {
        for (int u : ends[e]) {
          if (piece[u] < 0) {
            piece[u] = pieces;
            stack.push_back(u);
          }
        }
      }
    }
    ++pieces;
  }
  Strokes strokes;
  for (int pc = 0; pc < pieces; ++pc) {
    std::vector<int> odd;
    int any = -1;
    for (std::size_t v = 0; v < g.nodes.size(); ++v) {
      if (piece[v] != pc) continue;
      any = static_cast<int>(v);
      if (incident[v].size() % 2 == 1) odd.push_back(static_cast<int>(v));
    }
    std::vector<std::vector<int>> local = incident;  // this piece's lists, then pen-up edges
    std::vector<std::array<int, 2>> all_ends = ends;
    std::vector<char> pen_up(all_ends.size(), 0);
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
      const int e = static_cast<int>(all_ends.size());
      all_ends.push_back({odd[i], odd[best]});
      pen_up.push_back(1);
      local[odd[i]].push_back(e);
      local[odd[best]].push_back(e);
    }
    // Hierholzer's algorithm: an Euler circuit as a sequence of (edge, forward) steps.
    std::vector<char> used(all_ends.size(), 0);
    std::vector<std::size_t> cursor(local.size(), 0);
    const int start = odd.empty() ? any : odd.front();
    std::vector<std::pair<int, int>> stack{{start, -1}};  // (node, edge taken to reach it)
    std::vector<std::pair<int, int>> circuit;
    while (!stack.empty()) {
      const int v = stack.back().first;
      auto& c = cursor[v];
      while (c < local[v].size() && used[local[v][c]]) ++c;
      if (c == local[v].size()) {
        circuit.push_back(stack.back());
        stack.pop_back();
        continue;
      }
      const int e = local[v][c];
      used[e] = 1;
      const int u = all_ends[e][0] == v ? all_ends[e][1] : all_ends[e][0];
      stack.push_back({u, e});
    }
    std::reverse(circuit.begin(), circuit.end());
    // circuit[k] = (node reached, edge used from circuit[k-1]); split at pen-up edges.
    Strokes piece_strokes;
    Stroke current;
    for (std::size_t k = 1; k < circuit.size(); ++k) {
      const int e = circuit[k].second;
      const int from = circuit[k - 1].first;
      if (pen_up[e]) {
        if (!current.empty()) piece_strokes.push_back(std::move(current));
        current.clear();
        continue;
      }
      const auto& px = g.edges[e].pixels;
      const bool forward = g.edges[e].a == from;
      const std::size_t skip = current.empty() ? 0 : 1;  // the shared node is already there
      if (forward) {
        current.insert(current.end(), px.begin() + static_cast<long>(skip), px.end());
      } else {
        current.insert(current.end(), px.rbegin() + static_cast<long>(skip), px.rend());
      }
    }
    if (!current.empty()) {
      // The circuit wrapped: its last stroke continues into its first (no pen-up between).
      if (!piece_strokes.empty() && !odd.empty() && pen_up[circuit[1].second] == 0) {
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
