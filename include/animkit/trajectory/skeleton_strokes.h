#pragma once
// From a one-pixel skeleton to pen strokes: the skeleton becomes a graph (ends and junctions
// are nodes, the pixel chains between them are edges), each connected piece is covered by as
// few strokes as its odd junctions allow (every edge drawn exactly once: an Euler path over
// the graph with pen-up jumps between paired odd nodes), and the strokes are ordered and
// turned to keep the pen-up travel between them short.
#include <vector>

#include "animkit/trajectory/binary_image.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

struct SkeletonGraph {
  struct Node {
    Point2 position;  ///< pixel coordinates (x right, y down), the centroid of its pixels
    int degree = 0;   ///< edge ends at this node
  };
  struct Edge {
    int a = 0, b = 0;            ///< node indices (a == b for a loop)
    std::vector<Point2> pixels;  ///< from node a to node b, both node positions included
  };
  std::vector<Node> nodes;
  std::vector<Edge> edges;
};

/// The graph of a skeleton (as thin() leaves it). Pixels are joined by m-adjacency: a diagonal
/// step only where neither pixel beside it is ink, so a staircase is a chain, not triangles.
/// Touching junction pixels merge into one node; a closed loop with no junction gets one node.
/// Lone pixels are dropped.
SkeletonGraph skeleton_graph(const BinaryImage& skeleton);

/// Removes spurs: edges from an end to a junction no longer than `max_length` (arc length,
/// pixels). Thinning grows them where a thick stroke turns a corner; left in, each adds two
/// odd nodes and so a stroke. Returns how many it removed.
int prune_spurs(SkeletonGraph& graph, double max_length);

/// Strokes covering every edge once, in pixel coordinates (x right, y down). A piece with 2k
/// odd nodes (k > 0) gives k strokes, one with none gives one closed stroke.
Strokes cover_with_strokes(const SkeletonGraph& graph);

/// Orders strokes (reversing open ones and rotating closed ones where that helps) so each
/// starts near where the previous one ended: greedy nearest neighbour from the first stroke.
Strokes order_for_short_travel(Strokes strokes);

/// Total pen-up distance between consecutive strokes.
double travel_length(const Strokes& strokes);

}  // namespace animkit
