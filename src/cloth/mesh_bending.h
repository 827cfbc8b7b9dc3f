#pragma once
// The bending element across an interior edge of a triangle mesh: the quadratic bending model
// of Bergou, Wardetzky, Harmon, Zorin, Grinspun 2006 ("A quadratic bending model for
// inextensible surfaces", per-edge form of its section 4). For the edge x0-x1 shared by the
// triangles (x0, x1, x2) and (x0, x1, x3), with alpha_i, beta_i the angles at x_i in the first
// and second triangle,
//   w = (cot alpha1 + cot beta1, cot alpha0 + cot beta0, -cot alpha0 - cot alpha1,
//        -cot beta0 - cot beta1),   E = 1/2 c |sum_i w_i x_i|^2,
// with w computed once at rest (flat): sum w_i = 0 and sum w_i x_i = 0 at rest, so any affine
// map of the flat rest shape, rigid motions included, costs no bending energy.
//
// Why c = B / (A0 + A1). In the edge's frame (u along the edge, v across, rest x0, x1 at
// u = -l/2, l/2, apexes at (u2, h0) and (u3, -h1)), bending the sheet by a small normal
// displacement z = 1/2 (a u^2 + 2 b u v + c v^2) (curvature tensor S = [a b; b c]) gives
//   |sum w_i x_i| = l theta,   theta = c (h0 + h1) / 2 + b (u2 - u3)
//                                      + a ((u2^2 - l^2/4) / h0 + (u3^2 - l^2/4) / h1) / 2,
// theta being the dihedral angle. On an equilateral mesh (h = l sqrt 3 / 2, u2 = u3 = 0),
// theta = l (3 S_perp - S_par) / (2 sqrt 3); with c_e = B / (A0 + A1) = B / (l h) the edge
// stores 1/2 B (1/3) (3 S_perp - S_par)^2 per unit of its area (A0 + A1) / 3, and the three edge
// directions average a cylinder of curvature kappa = 1/R (S = kappa n n^T) to exactly
// 1/2 B kappa^2 per unit area, whatever its axis. (The 3 / (A0 + A1) of discrete shells is
// right for a sphere, not for the developable shapes cloth bends into: it gives 3/2 B kappa^2.)
// On a grid's right triangles the edges along the grid give theta = s S_zz and s S_xx, the
// diagonals -sqrt 2 s S_xz: exactly 1/2 B kappa^2 for a cylinder along a grid axis, anisotropic
// about the diagonals (3x across one of them, 1x across the other), as the grid's own
// three-particle bends are (1/2x at 45 degrees).
#include <array>

#include "animkit/core/types.h"

namespace animkit {

struct EdgeBend {
  std::array<double, 4> weights{};  ///< w over (x0, x1, x2, x3), dimensionless
  double stiffness = 0.0;           ///< c = B / (A0 + A1), N/m for B in N m
};

/// The element over the rest positions x0, x1 (the shared edge), x2, x3 (the opposite
/// vertices) for bending stiffness B >= 0. Expects two triangles of nonzero area.
EdgeBend edge_bend(const std::array<Vec3, 4>& x, double bending);

}  // namespace animkit
