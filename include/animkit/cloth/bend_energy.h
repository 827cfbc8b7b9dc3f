#pragma once
// One bending element's energy and derivatives (see BendDesc), kept together so they are tested
// together against finite differences. With w = (1, -2, 1) over particles (a, b, c) and
// e = x_a - 2 x_b + x_c:
//   E = 1/2 c |e|^2,   dE/dx_i = c w_i e,   d2E/dx_i dx_j = c w_i w_j I   (constant).
// By |u + v|^2 = 2|u|^2 + 2|v|^2 - |u - v|^2 with u = x_a - x_b, v = x_c - x_b, the Hessian
// is that of zero-rest-length springs of stiffness 2c on (a, b) and (b, c) and -c on (a, c):
// in the per-spring block form [K -K; -K K] it adds 2c I, 2c I and -c I to those springs' K.
#include "animkit/core/types.h"

namespace animkit {

/// x_a - 2 x_b + x_c: the line's second difference at b.
inline Vec3 bend_vector(const Vec3& x_a, const Vec3& x_b, const Vec3& x_c) {
  return x_a - 2.0 * x_b + x_c;
}

inline double bend_energy(const Vec3& x_a, const Vec3& x_b, const Vec3& x_c, double stiffness) {
  return 0.5 * stiffness * bend_vector(x_a, x_b, x_c).squaredNorm();
}

/// The coefficients w_i of dE/dx_i = c w_i e, and the K added to the springs (a, b), (b, c),
/// (a, c) per unit stiffness (times I).
inline constexpr double kBendWeights[3] = {1.0, -2.0, 1.0};
inline constexpr double kBendCouplings[3] = {2.0, 2.0, -1.0};

}  // namespace animkit
