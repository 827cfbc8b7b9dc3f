#pragma once
// One spring's elastic energy and its first and second derivatives, kept together so they are
// tested together against finite differences (SPEC.md section 4).
//
// For particles a, b with d = x_a - x_b, l = |d|, u = d / l, stiffness k and rest length L:
//   E       = 1/2 k (l - L)^2
//   dE/dx_a = k (l - L) u                     (dE/dx_b = -dE/dx_a)
//   d2E/dx_a2 = k [ u u^T + (1 - L/l) (I - u u^T) ] =: K   (the 6x6 Hessian is [K -K; -K K])
// K is indefinite when the spring is compressed (l < L makes 1 - L/l negative). Newton needs a
// positive semidefinite Hessian for its step to be a descent direction, so the projected
// Hessian clamps (1 - L/l) at zero: the compressed spring keeps its axial stiffness k u u^T and
// gets no (negative) transverse stiffness. That is the exact PSD projection of each 3x3 block.
#include <Eigen/Core>

#include "animkit/core/types.h"

namespace animkit {

using Mat3 = Eigen::Matrix3d;

/// 1/2 k (|x_a - x_b| - L)^2.
double spring_energy(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length);

/// dE/dx_a (dE/dx_b is its negative). Zero when the particles coincide.
Vec3 spring_gradient(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length);

/// The 3x3 block K of the spring's Hessian [K -K; -K K].
/// `projected` clamps the transverse term at zero (PSD); false gives the exact Hessian.
Mat3 spring_hessian_block(const Vec3& x_a, const Vec3& x_b, double stiffness, double rest_length,
                          bool projected = true);

}  // namespace animkit
