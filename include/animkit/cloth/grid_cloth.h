#pragma once
// The lab's cloth and any n x n grid like it.
#include <optional>

#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/material.h"
#include "animkit/core/types.h"

namespace animkit {

/// Which particles of a grid are pinned.
enum class GridPins {
  corners,  ///< the two corners of the edge i = 0 (the lab's)
  edge,     ///< the whole edge i = 0 (a flag on its pole)
  none,     ///< none: a free sheet (dropped, draped)
};

/// An (n+1) x (n+1) grid of particles in the plane y = height, spanning `size` along x and z:
/// particle (i, j) at (i * size / n, height, j * size / n - size / 2). Springs join each
/// particle to its neighbours at distance 1 and 2 along both grid axes and at distance 1 along
/// both diagonals; the two corners of the edge i = 0 are pinned. Defaults: the lab's cloth
/// (11 x 11 particles, spacing 0.2, y = 1.5, mass 1, stiffness 100, damping 0.2, gravity 0.3).
/// With a `material`, the sheet is physical instead (see material.h): sizes in metres, masses
/// and stiffnesses from the material, bends instead of the distance-2 springs.
struct GridClothOptions {
  int cells = 10;            ///< n >= 1: cells per side, n + 1 particles per side
  double size = 2.0;         ///< side length (scene units); spacing = size / cells
  double height = 1.5;       ///< y of the plane
  double mass = 1.0;         ///< per particle, > 0
  double stiffness = 100.0;  ///< k of every spring (force per unit length), in kStiffnessRange
  double damping = 0.2;      ///< the springs' dashpot coefficient (ClothDesc::damping)
  double gravity = 0.3;      ///< acceleration along -y (units/s^2), in kGravityRange
  /// A physical material: replaces mass, stiffness and damping (and the distance-2 springs).
  std::optional<ClothMaterial> material = std::nullopt;
  GridPins pins = GridPins::corners;  ///< which particles are pinned (default: the lab's corners)
  /// Placement of the sheet laid out as above: turned by `rotation` (unit) about its centre
  /// (size / 2, height, 0), then moved by `offset` (world space, scene units). Defaults: the
  /// lab's flat sheet where it is.
  Quat rotation = Quat::Identity();
  Vec3 offset = Vec3::Zero();  ///< translation applied after the rotation (scene units)

  /// The first out-of-range option, or nothing. Cells are capped at kMaxGridCells; a material
  /// must give particle masses and stiffnesses inside parameter_ranges.h at this resolution.
  std::optional<Error> validate() const;
};

/// Largest grid make_grid_cloth() accepts per side: 251,001 particles and 1.5 million springs,
/// a few hundred MB of solver workspace.
constexpr int kMaxGridCells = 500;

/// The grid's description; triangles split each cell along its (i,j)-(i+1,j+1) diagonal.
/// Check the options with validate() first: invalid ones give an invalid description.
ClothDesc make_grid_cloth(const GridClothOptions& options = {});

/// Index of particle (i, j) in a grid of `cells` cells per side.
inline int grid_index(int cells, int i, int j) {
  return i * (cells + 1) + j;
}

}  // namespace animkit
