#include "animkit/cloth/preconditioned_cg.h"

#include "../core/parallel.h"
#include "stacked_vectors.h"

namespace animkit {

namespace {

using Acc = std::array<double, 1>;

// The vectors hold 3 coordinates per particle; loops run per particle.
double dot(const Eigen::VectorXd& u, const Eigen::VectorXd& v, CgWorkspace& w) {
  const int n = static_cast<int>(u.size() / 3);
  return parallel::sum<1>(n, w.partials,
                          [&](int i, Acc& acc) { acc[0] += at(u, i).dot(at(v, i)); })[0];
}

}  // namespace

CgWorkspace::CgWorkspace(int particles)
    : r(3 * particles),
      z(3 * particles),
      p(3 * particles),
      ap(3 * particles),
      partials(static_cast<std::size_t>(parallel::chunk_count(particles))) {}

PcgResult preconditioned_cg(const ClothModel& model, const BlockHessian& a,
                            const Eigen::VectorXd& b, Eigen::VectorXd& x, double tolerance,
                            int max_iterations, const Preconditioner& precondition, CgWorkspace& w,
                            CgStart start) {
  return preconditioned_cg(
      [&](const Eigen::VectorXd& p, Eigen::VectorXd& ap) { a.multiply(model, p, ap); }, b, x,
      tolerance, max_iterations, precondition, w, start);
}

PcgResult preconditioned_cg(const LinearOperator& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                            double tolerance, int max_iterations,
                            const Preconditioner& precondition, CgWorkspace& w, CgStart start) {
  const int n = static_cast<int>(b.size() / 3);
  PcgResult result;
  if (start == CgStart::zero) x.setZero();
  const double b_norm = std::sqrt(dot(b, b, w));
  if (b_norm == 0.0) {
    x.setZero();
    result.converged = true;
    return result;
  }
  const double threshold = tolerance * b_norm;
  double r_norm = b_norm;
  if (start == CgStart::zero) {
    w.r = b;
  } else {
    a(x, w.ap);
    w.r = b - w.ap;
    r_norm = std::sqrt(dot(w.r, w.r, w));
    if (r_norm <= threshold) {
      result.relative_residual = r_norm / b_norm;
      result.converged = true;
      return result;
    }
  }
  precondition(w.r, w.z);
  w.p = w.z;
  double rz = dot(w.r, w.z, w);
  // With the exact Hessian the preconditioner itself can be indefinite; then r.z may be <= 0
  // and CG has no meaning: report it like negative curvature, so the caller projects.
  if (!(rz > 0.0)) {
    result.indefinite = true;
    result.relative_residual = 1.0;
    return result;
  }
  while (result.iterations < max_iterations) {
    a(w.p, w.ap);
    const double curvature = dot(w.p, w.ap, w);
    if (!(curvature > 0.0)) {
      result.indefinite = true;
      break;
    }
    const double alpha = rz / curvature;
    // x += alpha p, r -= alpha Ap and |r|^2 in one pass.
    const double r2 = parallel::sum<1>(n, w.partials, [&](int i, Acc& acc) {
      x.segment<3>(3 * i) += alpha * at(w.p, i);
      w.r.segment<3>(3 * i) -= alpha * at(w.ap, i);
      acc[0] += w.r.segment<3>(3 * i).squaredNorm();
    })[0];
    ++result.iterations;
    r_norm = std::sqrt(r2);
    if (r_norm <= threshold) break;
    precondition(w.r, w.z);
    const double rz_next = dot(w.r, w.z, w);
    if (!(rz_next > 0.0)) {
      result.indefinite = true;
      break;
    }
    const double beta = rz_next / rz;
    parallel::for_each(n, [&](int i) { w.p.segment<3>(3 * i) = at(w.z, i) + beta * at(w.p, i); });
    rz = rz_next;
  }
  result.relative_residual = r_norm / b_norm;
  result.converged = r_norm <= threshold;
  return result;
}

}  // namespace animkit
