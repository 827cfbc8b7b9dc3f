#pragma once
// Greedy vertex colouring of a conflict graph, so that the vertices of one colour can be updated
// independently (in parallel) by a Gauss-Seidel-type solver such as Vertex Block Descent (Chen
// et al. 2024, section 3.5): no two vertices of one colour share an element.
#include <array>
#include <span>
#include <vector>

#include "animkit/cloth/cloth_model.h"

namespace animkit {

/// Vertices grouped by colour: no two vertices joined by an edge have the same colour.
struct GraphColoring {
  std::vector<int> color;     ///< per vertex: its colour, in [0, color_count())
  std::vector<int> vertices;  ///< every vertex once, grouped by colour, increasing within one
  std::vector<int> offsets;   ///< colour c holds vertices[offsets[c], offsets[c + 1])

  /// Number of colours (0 for an empty colouring).
  int color_count() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  /// Colour c's vertices, increasing; 0 <= c < color_count().
  std::span<const int> members(int c) const {
    return std::span<const int>(vertices).subspan(
        static_cast<std::size_t>(offsets[c]),
        static_cast<std::size_t>(offsets[c + 1] - offsets[c]));
  }
};

/// Greedy colouring in vertex order: each vertex takes the smallest colour none of its
/// already-coloured neighbours has (at most max degree + 1 colours). Deterministic: the same
/// graph gives the same colours. Edges (a, b) with a != b, both in [0, vertex_count); repeated
/// edges are allowed.
GraphColoring greedy_coloring(int vertex_count, std::span<const std::array<int, 2>> edges);

/// The cloth's conflict graph coloured: two particles conflict when they share a spring (of any
/// stiffness) or a bend.
GraphColoring color_cloth_particles(const ClothModel& model);

/// Whether no edge joins two vertices of one colour and every vertex is listed once under its
/// colour (for tests and asserts).
bool is_valid_coloring(const GraphColoring& coloring, std::span<const std::array<int, 2>> edges);

/// The conflict edges of a cloth: each spring, and the three pairs of each bend.
std::vector<std::array<int, 2>> cloth_conflict_edges(const ClothModel& model);

}  // namespace animkit
