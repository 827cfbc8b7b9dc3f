#pragma once
// A block sparse matrix (src/cloth/block_sparse_matrix.h) as a dense one, so tests can check
// the multigrid's sparse products against plain dense arithmetic.
#include <Eigen/Core>

#include "../../src/cloth/block_sparse_matrix.h"

namespace animkit::testing_support {

inline Eigen::MatrixXd dense(const BlockSparseMatrix<3, 3>& m) {
  Eigen::MatrixXd d = Eigen::MatrixXd::Zero(3 * m.block_rows, 3 * m.block_cols);
  for (int i = 0; i < m.block_rows; ++i) {
    for (int k = m.row_start[i]; k < m.row_start[i + 1]; ++k)
      d.block<3, 3>(3 * i, 3 * m.column[k]) += m.values[k];
  }
  return d;
}

}  // namespace animkit::testing_support
