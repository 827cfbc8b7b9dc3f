#pragma once
// A sparse Cholesky factor L re-stored by supernodes, for triangular solves with three
// right-hand sides (the x, y and z coordinates) at once. A (fundamental) supernode is a run of
// consecutive columns of L whose patterns below the run are the same; its values are a dense
// lower triangle and a dense rectangle whose rows share one list of row indices. A solve then
// reads each row index, and gathers and scatters each entry of the right-hand side, once per
// supernode instead of once per column: the solve is bound by memory traffic, not arithmetic.
// The elimination of the separators of a nested-dissection-like (AMD) ordering gives wide
// supernodes that hold most of L's non-zeros.
#include <Eigen/SparseCore>
#include <vector>

namespace animkit {

/// A sparse Cholesky factor L stored by supernodes, for solves with three right-hand sides.
class SupernodalFactor {
 public:
  /// Takes L's values (lower triangular, compressed column-major, each column's rows sorted
  /// with the diagonal first: what Eigen's simplicial Cholesky stores). The supernodes are
  /// found on the first call; later calls must pass a factor with the same pattern and only
  /// copy values (no allocation).
  void assign(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower);

  /// Solves L L^T x = b in place; x holds row i's three right-hand sides at x[3i..3i+2].
  void solve(double* x) const;

  /// Number of supernodes found (0 before the first assign()).
  int supernode_count() const { return static_cast<int>(supernodes_.size()); }

 private:
  struct Supernode {
    int first_column = 0, width = 0;
    int rows_begin = 0, row_count = 0;  // into rows_: the shared rows below the triangle
    int values_begin = 0;               // into values_: the w x w triangle (column-major), then the
                                        // row_count x w rectangle (row-major)
  };
  void find_supernodes(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower);

  std::vector<Supernode> supernodes_;
  std::vector<int> rows_;
  std::vector<double> values_;
};

}  // namespace animkit
