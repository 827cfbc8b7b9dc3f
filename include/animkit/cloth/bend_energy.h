#pragma once
// One bending element's energy and derivatives (see BendDesc), kept together so they are tested
// together against finite differences. With weights w over particles p_0..p_3 (3 or 4 of them)
// and e = sum_i w_i x_i:
//   E = 1/2 c |e|^2,   dE/dx_i = c w_i e,   d2E/dx_i dx_j = c w_i w_j I   (constant).
// With sum_i w_i = 0 the Hessian is that of zero-rest-length springs on the pairs (i, j) with
// K_ij = -c w_i w_j (times I): in the per-spring block form [K -K; -K K] the off-diagonal block
// is -K = c w_i w_j and the diagonal one sum_{j != i} K_ij = -c w_i (sum_j w_j - w_i) =
// c w_i^2. The grid's line element w = (1, -2, 1) gives K = 2c on (a, b) and (b, c), -c on (a, c).
#include <Eigen/Core>
#include <array>

#include "animkit/core/types.h"

namespace animkit {

/// Most particles a bend joins; an unused last slot holds particle -1 and weight 0.
inline constexpr int kMaxBendParticles = 4;
using BendParticles = std::array<int, kMaxBendParticles>;
using BendWeights = std::array<double, kMaxBendParticles>;

/// The particle pairs (slot i, slot j) of a bend whose springs carry its Hessian blocks, the
/// three of a three-particle bend first.
inline constexpr std::array<std::array<int, 2>, 6> kBendPairs{
    {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}}};

/// How many slots of `p` are used (3 or 4).
inline int bend_size(const BendParticles& p) {
  return p[3] < 0 ? 3 : 4;
}

/// sum_i w_i x_i over the used slots, x being positions (or displacements) particle-major.
/// Added slot by slot from the first, so the line element gives x_a - 2 x_b + x_c to the bit.
inline Vec3 bend_vector(const Eigen::VectorXd& x, const BendParticles& p, const BendWeights& w) {
  Vec3 e = w[0] * x.segment<3>(3 * p[0]);
  e += w[1] * x.segment<3>(3 * p[1]);
  e += w[2] * x.segment<3>(3 * p[2]);
  if (p[3] >= 0) e += w[3] * x.segment<3>(3 * p[3]);
  return e;
}

inline double bend_energy(const Eigen::VectorXd& x, const BendParticles& p, const BendWeights& w,
                          double stiffness) {
  return 0.5 * stiffness * bend_vector(x, p, w).squaredNorm();
}

/// K of pair (i, j) per the derivation above: -c w_i w_j.
inline double bend_coupling(const BendWeights& w, int i, int j, double stiffness) {
  return -(w[i] * w[j]) * stiffness;
}

}  // namespace animkit
