#include "animkit/trajectory/skeleton_graph.h"

#include <algorithm>
#include <set>
#include <unordered_map>

namespace animkit {

namespace {

// m-adjacent ink neighbours of pixel p (index y * width + x): the 4-neighbours, and a diagonal
// one only when neither pixel between them is ink. Computed on demand: a skeleton is a few
// thousand pixels of a raster that may have millions.
std::vector<int> m_neighbours(const BinaryImage& im, int p) {
  const int x = p % im.width, y = p / im.width;
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
  std::vector<int> ink;
  for (std::size_t p = 0; p < im.pixels.size(); ++p) {
    if (im.pixels[p]) ink.push_back(static_cast<int>(p));
  }
  std::unordered_map<int, std::vector<int>> adjacent;
  adjacent.reserve(ink.size());
  for (int p : ink) adjacent.emplace(p, m_neighbours(im, p));
  const auto degree = [&](int p) { return adjacent.at(p).size(); };

  // Node pixels: ends (one neighbour), junctions (three or more), dots (none); touching
  // junction pixels form one node.
  std::unordered_map<int, int> node_of;
  std::vector<std::vector<int>> node_pixels;
  for (int p : ink) {
    if (node_of.contains(p) || degree(p) == 2) continue;
    const int id = static_cast<int>(node_pixels.size());
    node_pixels.emplace_back();
    std::vector<int> stack{p};
    node_of[p] = id;
    while (!stack.empty()) {
      const int q = stack.back();
      stack.pop_back();
      node_pixels[id].push_back(q);
      if (degree(q) < 3) continue;  // an end or a dot is a node on its own
      for (int r : adjacent.at(q)) {
        if (!node_of.contains(r) && degree(r) >= 3) {
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
  for (const auto& pixels : node_pixels) {
    add_node(pixels);
    g.nodes.back().dot = pixels.size() == 1 && degree(pixels.front()) == 0;
  }
  const auto node = [&](int p) {
    const auto it = node_of.find(p);
    return it == node_of.end() ? -1 : it->second;
  };

  // Walks from node pixel `start` through its neighbour `first` along chain pixels to the
  // next node pixel, marking the chain visited.
  std::set<int> visited;
  std::set<std::pair<int, int>> used_steps;  // (node pixel, first chain pixel) walked
  const auto trace = [&](int start, int first) {
    std::vector<int> chain{start};
    int previous = start, current = first;
    while (node(current) < 0) {
      chain.push_back(current);
      visited.insert(current);
      const auto& next = adjacent.at(current);
      const int step = next[0] == previous ? next[1] : next[0];
      previous = current;
      current = step;
    }
    chain.push_back(current);
    return chain;
  };
  const auto add_edge = [&](const std::vector<int>& chain) {
    SkeletonGraph::Edge e;
    e.a = node(chain.front());
    e.b = node(chain.back());
    e.pixels.push_back(g.nodes[e.a].position);
    for (std::size_t i = 1; i + 1 < chain.size(); ++i) e.pixels.push_back(centre_of(chain[i], w));
    e.pixels.push_back(g.nodes[e.b].position);
    ++g.nodes[e.a].degree;
    ++g.nodes[e.b].degree;
    g.edges.push_back(std::move(e));
  };
  for (int p : ink) {
    if (node(p) < 0) continue;
    for (int q : adjacent.at(p)) {
      if (node(q) == node(p)) continue;  // inside one junction
      if (used_steps.contains({p, q})) continue;
      const std::vector<int> chain = trace(p, q);
      // The same edge walked back from its other end must not be added again.
      used_steps.insert({p, q});
      used_steps.insert({chain.back(), chain[chain.size() - 2]});
      add_edge(chain);
    }
  }
  // Loops with no node (a ring): one node on the loop, one edge round it.
  for (int p : ink) {
    if (visited.contains(p) || node(p) >= 0 || degree(p) != 2) continue;
    node_of[p] = static_cast<int>(g.nodes.size());
    add_node({p});
    visited.insert(p);
    add_edge(trace(p, adjacent.at(p)[0]));
  }
  return g;
}

int prune_spurs(SkeletonGraph& g, double max_length) {
  // Candidates: short edges from an end to a junction, shortest first.
  std::vector<std::pair<double, std::size_t>> candidates;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const auto& edge = g.edges[e];
    const int da = g.nodes[edge.a].degree, db = g.nodes[edge.b].degree;
    const double length = stroke_length(edge.pixels);
    if (((da == 1 && db >= 3) || (db == 1 && da >= 3)) && length <= max_length) {
      candidates.emplace_back(length, e);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  // A junction keeps at least two branches (the line through it), so its degree never drops
  // below 2 and the piece keeps its edges.
  std::vector<char> removed(g.edges.size(), 0);
  int count = 0;
  for (const auto& [length, e] : candidates) {
    SkeletonGraph::Edge& edge = g.edges[e];
    const int junction = g.nodes[edge.a].degree == 1 ? edge.b : edge.a;
    if (g.nodes[junction].degree <= 2) continue;
    removed[e] = 1;
    --g.nodes[edge.a].degree;
    --g.nodes[edge.b].degree;
    ++count;
  }
  std::vector<SkeletonGraph::Edge> kept;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    if (!removed[e]) kept.push_back(std::move(g.edges[e]));
  }
  g.edges = std::move(kept);
  return count;
}

}  // namespace animkit
