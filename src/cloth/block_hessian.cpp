#include "animkit/cloth/block_hessian.h"

#include "../core/parallel.h"

namespace animkit {

void BlockHessian::multiply(const ClothModel& model, const Eigen::VectorXd& p,
                            Eigen::VectorXd& y) const {
  // A p = (M / h^2) p + sum over springs of [K -K; -K K] (p_a, p_b). Row i gathers, over its
  // springs s to particles j in spring order, K_s (p_i - p_j): each row is written once, so
  // rows split over threads with the same bits as one thread.
  const int n = static_cast<int>(inertia.size());
  parallel::for_each(n, [&](int i) {
    const auto row = static_cast<Eigen::Index>(3 * i);
    Eigen::Vector3d sum = inertia[i] * p.segment<3>(row);
    // A pinned particle is not an unknown: its row stays the identity's, and its p entries
    // (zero) are left out of its free neighbours' rows.
    if (!model.pinned[i]) {
      const Eigen::Vector3d pi = p.segment<3>(row);
      for (int e = incidence.spring_start[i]; e < incidence.spring_start[i + 1]; ++e) {
        const int s = incidence.spring_entry[e] >> 1;
        const int j = model.springs[s][1 - (incidence.spring_entry[e] & 1)];
        const Eigen::Vector3d d = model.pinned[j] ? pi : Eigen::Vector3d(pi - p.segment<3>(3 * j));
        sum.noalias() += coupling[s] * d;
      }
    }
    y.segment<3>(row) = sum;
  });
}

}  // namespace animkit
