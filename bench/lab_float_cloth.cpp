#include "lab_float_cloth.h"

#include <Eigen/SparseCholesky>
#include <algorithm>

namespace animkit::bench {

using Eigen::Vector3f;
using Mat3f = Eigen::Matrix3f;

namespace {
Vector3f at(const Eigen::VectorXf& v, int i) {
  return v.segment<3>(3 * i);
}
}  // namespace

LabFloatImplicitEuler::LabFloatImplicitEuler(const ClothModel& model)
    : model_(model), axis_(model.springs.size()) {}

float LabFloatImplicitEuler::objective(const Eigen::VectorXf& x) const {
  float inertia = 0.0f, elastic = 0.0f, damping = 0.0f;
  for (int i = 0; i < model_.particle_count(); ++i) {
    inertia += static_cast<float>(model_.mass[i]) * (at(x, i) - at(y_, i)).squaredNorm();
  }
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    const float stretch = (at(x, a) - at(x, b)).norm() - static_cast<float>(model_.rest_length[s]);
    elastic += 0.5f * static_cast<float>(model_.stiffness[s]) * stretch * stretch;
    const float q = (at(x, a) - at(x_start_, a) - at(x, b) + at(x_start_, b)).dot(axis_[s]);
    damping += q * q;
  }
  return inertia / (2 * h_ * h_) + elastic +
         static_cast<float>(model_.damping) / (2 * h_) * damping;
}

void LabFloatImplicitEuler::gradient(const Eigen::VectorXf& x, Eigen::VectorXf& g) const {
  for (int i = 0; i < model_.particle_count(); ++i) {
    g.segment<3>(3 * i) = static_cast<float>(model_.mass[i]) / (h_ * h_) * (at(x, i) - at(y_, i));
  }
  const float c = static_cast<float>(model_.damping) / h_;
  for (int s = 0; s < model_.spring_count(); ++s) {
    const auto [a, b] = model_.springs[s];
    const Vector3f d = at(x, a) - at(x, b);
    const float l = d.norm();
    const float q = (d - at(x_start_, a) + at(x_start_, b)).dot(axis_[s]);
    const Vector3f f = static_cast<float>(model_.stiffness[s]) *
                           (l - static_cast<float>(model_.rest_length[s])) / l * d +
                       c * q * axis_[s];
    g.segment<3>(3 * a) += f;
    g.segment<3>(3 * b) -= f;
  }
  for (int i = 0; i < model_.particle_count(); ++i) {
    if (model_.pinned[i]) g.segment<3>(3 * i).setZero();
  }
}

int LabFloatImplicitEuler::step(Eigen::VectorXf& x, Eigen::VectorXf& v, float h, float tolerance,
                                int max_iterations) {
  const int n = model_.particle_count();
  h_ = h;
  x_start_ = x;
  y_ = x + h * v;
  for (int i = 0; i < n; ++i) {
    if (model_.pinned[i])
      y_.segment<3>(3 * i) = at(x, i);
    else
      y_[3 * i + 1] -= h * h * static_cast<float>(model_.gravity);
  }
  for (int s = 0; s < model_.spring_count(); ++s) {
    axis_[s] = (at(x, model_.springs[s][0]) - at(x, model_.springs[s][1])).normalized();
  }
  Eigen::VectorXf xk = y_, g(3 * n), dx(3 * n);
  gradient(xk, g);
  const float g0 = g.norm();
  float fx = objective(xk);
  int k = 0;
  for (; k < max_iterations && g.norm() > tolerance * g0; ++k) {
    std::vector<Eigen::Triplet<float>> triplets;
    for (int i = 0; i < n; ++i) {
      const float diagonal = model_.pinned[i] ? 1.0f : static_cast<float>(model_.mass[i]) / (h * h);
      for (int c = 0; c < 3; ++c) triplets.emplace_back(3 * i + c, 3 * i + c, diagonal);
    }
    for (int s = 0; s < model_.spring_count(); ++s) {
      const auto [a, b] = model_.springs[s];
      const Vector3f d = at(xk, a) - at(xk, b);
      const float l = d.norm();
      const Vector3f u = d / l;
      const float t = std::max(0.0f, 1.0f - static_cast<float>(model_.rest_length[s]) / l);
      const Mat3f block = static_cast<float>(model_.stiffness[s]) *
                              (u * u.transpose() + t * (Mat3f::Identity() - u * u.transpose())) +
                          static_cast<float>(model_.damping) / h * axis_[s] * axis_[s].transpose();
      for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
          if (!model_.pinned[a]) triplets.emplace_back(3 * a + r, 3 * a + c, block(r, c));
          if (!model_.pinned[b]) triplets.emplace_back(3 * b + r, 3 * b + c, block(r, c));
          if (!model_.pinned[a] && !model_.pinned[b]) {
            triplets.emplace_back(3 * a + r, 3 * b + c, -block(r, c));
            triplets.emplace_back(3 * b + r, 3 * a + c, -block(r, c));
          }
        }
      }
    }
    Eigen::SparseMatrix<float> hessian(3 * n, 3 * n);
    hessian.setFromTriplets(triplets.begin(), triplets.end());
    Eigen::SimplicialLLT<Eigen::SparseMatrix<float>> llt(hessian);
    dx = llt.solve(-g);
    const float slope = g.dot(dx);
    float alpha = 2.0f, f_trial = 0.0f;
    int tries = 0;
    do {
      alpha *= 0.5f;
      f_trial = objective(xk + alpha * dx);
    } while (f_trial > fx + 1e-4f * alpha * slope && ++tries < 50);
    xk += alpha * dx;
    fx = f_trial;
    gradient(xk, g);
  }
  v = (xk - x) / h;
  for (int i = 0; i < n; ++i) {
    if (model_.pinned[i]) v.segment<3>(3 * i).setZero();
  }
  x = xk;
  return k;
}

}  // namespace animkit::bench
