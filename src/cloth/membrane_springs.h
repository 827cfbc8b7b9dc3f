#pragma once
// Spring stiffnesses on a triangle's edges that give it a material's membrane stiffness.
//
// A triangle of area A with edges e (rest length l_e, unit direction with components c_e, s_e
// along the material's warp and weft) under a uniform small strain eps stretches edge e by
// l_e (c^2 eps_ww + s^2 eps_ff + 2 c s eps_wf), so its springs store
//   sum_e 1/2 k_e l_e^2 (m_e . eps)^2 = A 1/2 eps^T C eps,   C = sum_e kappa_e m_e m_e^T,
// with Voigt strain eps = (eps_ww, eps_ff, gamma_wf), m_e = (c^2, s^2, c s) and
// kappa_e = k_e l_e^2 / A (N/m). So C11 = sum kappa c^4, C22 = sum kappa s^4 and
// C12 = C66 = sum kappa c^2 s^2: springs obey the Cauchy relation C12 = C66, and the membrane
// they represent has the Poisson ratio nu = C12 / C22 = shear / stretch (0.04 for cotton), an
// isotropic one only with nu = 1/3 (stretch = 3 shear). We match the three stiffnesses the
// grid's lattice mapping matches (material.h), C11 = C22 = stretch and C66 = shear:
//   [c_e^4; s_e^4; c_e^2 s_e^2] kappa = [stretch; stretch; shear],
// solved in the least-squares, minimum-norm sense when singular (an equilateral triangle with
// an edge on the warp: its other two edges look alike to these three sums), kappa clamped at 0.
// A right triangle with legs along warp and weft gets kappa = (S - G, S - G, 4 G), i.e.
// k = (S - G) / 2 on each leg and G on the hypotenuse: two such triangles per grid cell give the
// grid's axis springs S - G and C66 = G. What is left over is C16 = sum kappa c^3 s and C26 (a
// coupling of shear and stretch, of the order of the shear stiffness), which cancels between
// triangles of opposite orientation, but not on a mesh whose edges leave the warp and weft:
// there a stiff edge a little off the warp gives C16 ~ (S - G) c^3 s, far above the shear G of
// a cloth like cotton, and the sheet stretches more through the soft shear (measured in
// tests/cloth/mesh_resolution_test.cpp; a per-triangle FEM membrane would represent C exactly).
// (Van Gelder 1998, "Approximate simulation of elastic
// membranes by triangulated spring meshes", derives such stiffnesses for isotropic membranes;
// Delingette 2008, "Triangular springs for modeling nonlinear membranes", shows what springs
// alone cannot represent.)
#include <array>

#include "animkit/cloth/material.h"
#include "animkit/core/types.h"

namespace animkit {

/// Per edge (x0, x1), (x1, x2), (x2, x0) of the triangle, its share of spring stiffness (N/m,
/// >= 0). `warp`: the material's warp direction (world space, nonzero); where the triangle is
/// perpendicular to it, its first edge stands for the warp.
std::array<double, 3> membrane_spring_stiffness(const std::array<Vec3, 3>& x,
                                                const ClothMaterial& material, const Vec3& warp);

}  // namespace animkit
