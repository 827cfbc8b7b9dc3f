#pragma once
// A sparse matrix of fixed-size R x C blocks in compressed block rows (BSR): the storage of the
// multigrid hierarchy's operators (3x3 blocks per particle on the finest level) and of its
// prolongators. The pattern is built once per model; solves rewrite only `values`.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace animkit {

template <int R, int C>
struct BlockSparseMatrix {
  using Block = Eigen::Matrix<double, R, C>;

  int block_rows = 0;
  int block_cols = 0;
  std::vector<int> row_start{0};  ///< block_rows + 1 offsets into `column` and `values`
  std::vector<int> column;        ///< per block, ascending within a row
  std::vector<Block> values;      ///< per block

  int block_count() const { return static_cast<int>(column.size()); }

  /// Position of block (row, col) in `values`, or -1 when it is not stored.
  int find(int row, int col) const {
    const auto begin = column.begin() + row_start[row], end = column.begin() + row_start[row + 1];
    const auto at = std::lower_bound(begin, end, col);
    return at != end && *at == col ? static_cast<int>(at - column.begin()) : -1;
  }

  /// y = M x.
  void multiply(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    for (int i = 0; i < block_rows; ++i) {
      Eigen::Matrix<double, R, 1> sum = Eigen::Matrix<double, R, 1>::Zero();
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        sum.noalias() += values[k] * x.segment<C>(C * column[k]);
      y.segment<R>(R * i) = sum;
    }
  }

  /// y = M^T x.
  void multiply_transpose(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    y.setZero();
    for (int i = 0; i < block_rows; ++i) {
      const Eigen::Matrix<double, R, 1> xi = x.segment<R>(R * i);
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        y.segment<C>(C * column[k]).noalias() += values[k].transpose() * xi;
    }
  }

  /// y += M x.
  void multiply_add(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
    for (int i = 0; i < block_rows; ++i) {
      for (int k = row_start[i]; k < row_start[i + 1]; ++k)
        y.segment<R>(R * i).noalias() += values[k] * x.segment<C>(C * column[k]);
    }
  }
};

/// Builds a pattern (values zero) from each row's sorted, duplicate-free column list.
template <int R, int C>
BlockSparseMatrix<R, C> block_pattern(const std::vector<std::vector<int>>& rows, int block_cols) {
  BlockSparseMatrix<R, C> m;
  m.block_rows = static_cast<int>(rows.size());
  m.block_cols = block_cols;
  for (const std::vector<int>& row : rows) {
    m.column.insert(m.column.end(), row.begin(), row.end());
    m.row_start.push_back(static_cast<int>(m.column.size()));
  }
  m.values.assign(m.column.size(), BlockSparseMatrix<R, C>::Block::Zero());
  return m;
}

}  // namespace animkit
