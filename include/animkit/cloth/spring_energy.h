#pragma once
// One spring's elastic energy and its first and second derivatives, kept together so they are
// tested together against finite differences (docs/implicit-step.md).
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
#include <cmath>

#include "animkit/core/types.h"

namespace animkit {

using Mat3 = Eigen::Matrix3d;

// Inline: these run once per spring per evaluation, inside the solvers' innermost loops.

/// 1/2 k (|x_a - x_b| - L)^2.
inline double spring_energy(const Vec3& x_a, const Vec3& x_b, double stiffness,
                            double rest_length) {
  const double stretch = (x_a - x_b).norm() - rest_length;
  return 0.5 * stiffness * stretch * stretch;
}

/// dE/dx_a (dE/dx_b is its negative). Zero when the particles coincide.
inline Vec3 spring_gradient(const Vec3& x_a, const Vec3& x_b, double stiffness,
                            double rest_length) {
  const Vec3 d = x_a - x_b;
  const double length = d.norm();
  if (length == 0.0) return Vec3::Zero();  // direction undefined; E is not differentiable here
  return (stiffness * (length - rest_length) / length) * d;
}

/// The 3x3 block K of the spring's Hessian [K -K; -K K], written as
/// k [ (1 - t) u u^T + t I ] with t = 1 - L/l. `projected` clamps t at zero (PSD); false
/// gives the exact Hessian.
inline Mat3 spring_hessian_block(const Vec3& x_a, const Vec3& x_b, double stiffness,
                                 double rest_length, bool projected = true) {
  const Vec3 d = x_a - x_b;
  const double length2 = d.squaredNorm();
  // Coincident particles: no direction; the clamped transverse term is 0 and the axial one
  // has no axis, so the best PSD stand-in is the isotropic k I (what u u^T averages to x3).
  if (length2 == 0.0) return Mat3::Identity() * stiffness;
  const double length = std::sqrt(length2);
  double transverse = 1.0 - rest_length / length;
  if (projected && transverse < 0.0) transverse = 0.0;
  // k (1 - t) u u^T = k (1 - t) / l^2 d d^T: no normalization of d needed.
  Mat3 block = (stiffness * (1.0 - transverse) / length2) * (d * d.transpose());
  block.diagonal().array() += stiffness * transverse;
  return block;
}

}  // namespace animkit
