#pragma once
// Pen strokes over a skeleton graph: each connected piece is covered by as few strokes as its
// odd nodes allow, every edge drawn exactly once (an Euler path over the graph with pen-up
// jumps between paired odd nodes), and the strokes are ordered to keep pen-up travel short.
#include "animkit/trajectory/skeleton_graph.h"

namespace animkit {

/// Strokes covering every edge once, in pixel coordinates (x right, y down). A piece with 2k
/// odd nodes (k > 0) gives k strokes, one with none gives one closed stroke, a dot gives a
/// one-point stroke.
Strokes cover_with_strokes(const SkeletonGraph& graph);

/// Orders strokes (reversing open ones and rotating closed ones where that helps) so each
/// starts near where the previous one ended: greedy nearest neighbour from the first stroke.
Strokes order_for_short_travel(Strokes strokes);

/// Total pen-up distance between consecutive strokes.
double travel_length(const Strokes& strokes);

}  // namespace animkit
