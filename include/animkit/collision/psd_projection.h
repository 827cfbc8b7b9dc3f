#pragma once
// Projection of a small symmetric matrix onto the positive semidefinite cone: the nearest PSD
// matrix in the Frobenius norm, V max(Lambda, 0) V^T from the eigendecomposition (Higham 1988).
// IPC projects each contact pair's barrier Hessian this way before assembly, so Newton's
// direction is a descent direction (Li et al. 2020, section 5; Teran et al. 2005 did the same
// per element for elasticity). Fixed sizes only: a contact stencil has 2, 3 or 4 vertices (and a
// sphere's pair over a triangle's face lives in 5 directions, contact_pair.cpp).
#include <Eigen/Core>

namespace animkit {

/// The nearest PSD matrix to the symmetric `matrix` (only its lower triangle is read).
Eigen::Matrix<double, 5, 5> project_to_psd(const Eigen::Matrix<double, 5, 5>& matrix);
Eigen::Matrix<double, 6, 6> project_to_psd(const Eigen::Matrix<double, 6, 6>& matrix);
Eigen::Matrix<double, 9, 9> project_to_psd(const Eigen::Matrix<double, 9, 9>& matrix);
Eigen::Matrix<double, 12, 12> project_to_psd(const Eigen::Matrix<double, 12, 12>& matrix);

}  // namespace animkit
