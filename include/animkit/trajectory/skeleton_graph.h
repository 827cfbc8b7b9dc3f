#pragma once
// A one-pixel skeleton as a graph: ends and junctions are nodes, the pixel chains between them
// are edges. Thinning grows short spurs where a thick stroke turns a corner; they are pruned.
#include <vector>

#include "animkit/trajectory/binary_image.h"
#include "animkit/trajectory/strokes.h"

namespace animkit {

/// A one-pixel skeleton as a graph: ends, junctions and dots are nodes, pixel chains are edges.
struct SkeletonGraph {
  /// An end, a junction, the one node of a closed loop without junction, or a dot.
  struct Node {
    Point2 position;   ///< pixel coordinates (x right, y down), the centroid of its pixels
    int degree = 0;    ///< edge ends at this node
    bool dot = false;  ///< a lone skeleton pixel: drawn as a point
  };
  /// A chain of skeleton pixels between two nodes.
  struct Edge {
    /// Index in `nodes` of the node the edge starts at.
    int a = 0, b = 0;            ///< index in `nodes` of the node it ends at (a == b for a loop)
    std::vector<Point2> pixels;  ///< from node a to node b, both node positions included
  };
  std::vector<Node> nodes;  ///< every node; Edge::a and Edge::b index it
  std::vector<Edge> edges;  ///< every edge, each between two nodes (or one, for a loop)
};

/// The graph of a skeleton (as thin() leaves it). Pixels are joined by m-adjacency: a diagonal
/// step only where neither pixel beside it is ink, so a staircase is a chain, not triangles.
/// Touching junction pixels merge into one node; a closed loop with no junction gets one node;
/// a lone pixel is a node with no edge (a dot).
SkeletonGraph skeleton_graph(const BinaryImage& skeleton);

/// Removes spurs: edges from an end to a junction no longer than `max_length` (arc length,
/// pixels). At a junction of degree d at most d - 2 of them go, the shortest, so a junction
/// keeps the two branches that make it a line; a piece never loses its last edge. Returns how
/// many it removed.
int prune_spurs(SkeletonGraph& graph, double max_length);

}  // namespace animkit
