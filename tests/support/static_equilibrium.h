#pragma once
// A cloth's static equilibrium under gravity, for the tests that compare how materials hang.
#include <gtest/gtest.h>

#include <algorithm>

#include "animkit/cloth/incremental_potential.h"
#include "animkit/cloth/multigrid_pcg.h"

namespace animkit::testing_support {

// The sheet's potential energy (elastic, bending, gravity) is g of a step so long that
// inertia no longer counts: with v = 0, y = x_n - h^2 g e_y and M (x - y) / h^2 = M (x - x_n) /
// h^2 + M g e_y, so grad g is the static residual plus M (x - x_n) / h^2, which is
// |x - x_n| / (g h^2), about 1e-9 at h = 1e4, of the weights: far below what is measured here.
// (g keeps its accuracy as h grows: x - y loses eps |y| = eps h^2 g, which the 1/h^2 scales
// back to eps of the weights.)
constexpr double kStatic = 1e4;

// Static equilibrium by Newton on the potential energy: the projected (SPD) Hessian makes each
// direction a descent direction, solved by multigrid PCG (faster here than block-Jacobi PCG and
// the direct LDL^T, increasingly so as the grid refines), with an Armijo backtracking on g's
// cancellation-free difference. Stops at 1e-5 of the gradient at the start: the sags then
// agree with a solve to 1e-8 in all the digits compared.
inline Eigen::VectorXd static_equilibrium(const ClothModel& model, const Eigen::VectorXd& start) {
  IncrementalPotential potential(model);
  potential.prepare({start, Eigen::VectorXd::Zero(start.size())}, kStatic);
  MultigridPcg multigrid(model);
  BlockHessian hessian(model);
  Eigen::VectorXd x = start, gradient(x.size()), dx(x.size()), rhs(x.size());
  potential.gradient(x, gradient);
  const double initial = gradient.norm();
  for (int k = 0; k < 50 && gradient.norm() > 1e-5 * initial; ++k) {
    potential.hessian(x, hessian, /*projected=*/true);
    rhs = -gradient;
    multigrid.solve(hessian, rhs, dx, 0.01 * std::clamp(gradient.norm() / initial, 1e-3, 0.5),
                    1000);
    const double slope = gradient.dot(dx);
    EXPECT_LT(slope, 0.0);
    double alpha = 1.0;
    while (potential.difference(x, alpha * dx) > 1e-4 * alpha * slope && alpha > 1e-10)
      alpha *= 0.5;
    x += alpha * dx;
    potential.gradient(x, gradient);
  }
  EXPECT_LE(gradient.norm(), 1e-5 * initial);
  return x;
}

}  // namespace animkit::testing_support
