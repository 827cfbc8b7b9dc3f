#pragma once
// IPC's mollifier for nearly parallel edges (Li et al. 2020, section 4.3, eqs. 21-23).
//
// The edge-edge distance is not smooth where the edges turn parallel (the closest-feature case
// jumps between line-line and point-line there), so IPC multiplies the edge-edge barrier by
//   m(c) = -c^2 / eps_x^2 + 2 c / eps_x   for c < eps_x,   1 otherwise,
// with c = |(a1 - a0) x (b1 - b0)|^2 and eps_x = 1e-3 |a1 - a0|^2 |b1 - b0|^2 at rest: m goes
// to 0 (with zero slope in c) as the edges turn parallel, and m is C^1 at c = eps_x.
// Derivatives by the chain rule:
//   m'(c) = 2 (eps_x - c) / eps_x^2,  m''(c) = -2 / eps_x^2   (c < eps_x; 0 beyond)
//   grad m = m' grad c,  hess m = m'' grad c grad c^T + m' hess c
// with c's derivatives those of |u x v|^2 (see src/collision/reduced_derivatives.h).
#include "animkit/collision/distance.h"
#include "animkit/core/types.h"

namespace animkit {

/// eps_x = 1e-3 |a1 - a0|^2 |b1 - b0|^2 from the edges' rest positions (units: length^4).
/// Positive for edges of non-zero rest length.
double edge_edge_mollifier_threshold(const Vec3& a0_rest, const Vec3& a1_rest, const Vec3& b0_rest,
                                     const Vec3& b1_rest);

/// m(c) in [0, 1] for edges (a0, a1), (b0, b1) at the current positions; eps_x > 0 from
/// edge_edge_mollifier_threshold.
double edge_edge_mollifier(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1,
                           double eps_x);

/// m and its gradient and Hessian in (a0, a1, b0, b1); zero derivatives where c >= eps_x.
StencilDerivatives<4> edge_edge_mollifier_derivatives(const Vec3& a0, const Vec3& a1,
                                                      const Vec3& b0, const Vec3& b1, double eps_x);
/// m and its gradient alone (the same numbers).
StencilGradient<4> edge_edge_mollifier_gradient(const Vec3& a0, const Vec3& a1, const Vec3& b0,
                                                const Vec3& b1, double eps_x);

}  // namespace animkit
