#pragma once
// A cloth material in physical units, and the presets `--material` names. A grid cloth built
// from a material (GridClothOptions::material) gets its particle masses and spring and bend
// stiffnesses from these values and its spacing, so the same material hangs the same at any
// resolution:
// - mass: density x the particle's share of the sheet's area (s^2 inside, half on an edge, a
//   quarter at a corner);
// - a square lattice with axis springs k1 and two diagonal springs k2 per cell has, under a
//   uniform strain, the membrane stiffnesses C11 = k1 + k2 (N/m) and C66 = k2 (one diagonal
//   stretches by s gamma / sqrt 2 under a shear gamma, per cell of area s^2): so k1 = stretch -
//   shear and k2 = shear, independent of s. Axis springs on the border carry half (a border edge
//   has one cell, not two);
// - bending: 1/2 B kappa^2 per unit area per direction; a bend over three particles along a grid
//   line has |x_a - 2 x_b + x_c| ~ kappa s^2 and stands for an area s^2 (half on the border), so
//   its stiffness is B / s^2 (see bend_energy.h).
#include <optional>
#include <span>
#include <string_view>

#include "animkit/core/result.h"

namespace animkit {

/// A cloth material in physical units (SI), from which a sheet's masses and stiffnesses follow.
struct ClothMaterial {
  double density = 0.15;  ///< areal density, kg/m^2, in (1e-4, 1e3]
  double stretch = 1000;  ///< membrane stretch stiffness C11 (Young's modulus x thickness), N/m
  double shear = 40;      ///< membrane shear stiffness C66, N/m, in (0, stretch)
  double bending = 1e-5;  ///< bending stiffness B, N m (0: no bending resistance), <= 1e3
  /// Dashpot coefficient of every spring, N s/m (ClothDesc::damping), >= 0. Physical sheets
  /// rely on implicit Euler's own damping by default.
  double damping = 0.0;

  /// The first out-of-range value, named, or nothing.
  std::optional<Error> validate() const;
};

/// A named material (material_presets()) with the values' source.
struct MaterialPreset {
  std::string_view name;    ///< what --material accepts
  ClothMaterial material;   ///< the material's values
  std::string_view source;  ///< where the values come from
};

/// cotton, silk, denim, leather, rubber.
std::span<const MaterialPreset> material_presets();
/// The preset called `name`, or null.
const MaterialPreset* find_material(std::string_view name);

}  // namespace animkit
