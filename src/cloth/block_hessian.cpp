#include "animkit/cloth/block_hessian.h"

namespace animkit {

void BlockHessian::multiply(const ClothModel& model, const Eigen::VectorXd& p,
                            Eigen::VectorXd& y) const {
  for (std::size_t i = 0; i < diagonal.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(3 * i);
    y.segment<3>(k).noalias() = diagonal[i] * p.segment<3>(k);
  }
  for (std::size_t s = 0; s < coupling.size(); ++s) {
    const auto [a, b] = model.springs[s];
    // Off-diagonal blocks -K: y_a -= K p_b, y_b -= K p_a (K is zero for a pinned end).
    y.segment<3>(3 * a).noalias() -= coupling[s] * p.segment<3>(3 * b);
    y.segment<3>(3 * b).noalias() -= coupling[s] * p.segment<3>(3 * a);
  }
}

}  // namespace animkit
