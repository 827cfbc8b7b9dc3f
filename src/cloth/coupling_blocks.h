#pragma once
// Off-diagonal 3x3 blocks whose pattern changes from solve to solve: the couplings an energy
// term adds between particles the springs do not join (contact between a point and a triangle
// or two edges far apart on the cloth, once it folds onto itself). The multigrid hierarchy's
// fixed patterns come from the springs; these blocks ride beside them, on every level:
//
//   A_l + E_l on level l, E_{l+1} = P_l^T E_l P_l (its diagonal blocks added into A_{l+1}),
//
// so each level's operator is the Galerkin product of the full Hessian, contact included
// (Tamstorf, Jones & McCormick 2015, section 4, use P^T A P of the whole matrix). Only the
// pattern of E is rebuilt per solve, from a list of blocks: a sort of that list, no search in
// the fixed patterns. E is kept by its upper blocks (row < col), so every level stays exactly
// symmetric, and a sort with a stable tie-break keeps the sums in one order (same bits).
// Work vectors keep their capacity: once the contacts stop growing, nothing is allocated.
#include <Eigen/Core>
#include <vector>

#include "block_sparse_matrix.h"

namespace animkit {

class CouplingBlocks {
 public:
  using Matrix = BlockSparseMatrix<3, 3>;

  /// Starts an empty set of blocks for a level of `nodes` nodes.
  void clear(int nodes);
  /// Adds the block at (row, col), row != col, and its transpose at (col, row).
  void add(int row, int col, const Eigen::Matrix3d& value);
  /// Merges the blocks added since clear() into full(): both triangles, one block per
  /// (row, col), duplicates summed in the order they were added.
  void assemble();

  /// Both triangles, no diagonal blocks (valid after assemble()).
  const Matrix& full() const { return full_; }
  bool empty() const { return upper_.empty(); }

  /// A block of P^T E P on the next level's diagonal, one of the terms that sum to it.
  struct DiagonalPart {
    int node;
    Eigen::Matrix3d value;
  };
  /// The next level's couplings P^T E P through the prolongator `p` (this level's nodes to the
  /// next's): blocks between two aggregates go into `coarse` (assembled), blocks within one
  /// aggregate into `within`, in the order the next level's operator is to add them
  /// (add_within) after its Galerkin product.
  void restrict_to(const Matrix& p, CouplingBlocks& coarse,
                   std::vector<DiagonalPart>& within) const;
  /// a's diagonal blocks (at positions `diagonal`) += `within`'s parts, in their order.
  static void add_within(const std::vector<DiagonalPart>& within, Matrix& a,
                         const std::vector<int>& diagonal);

 private:
  struct Entry {
    int row, col;  // row < col
    Eigen::Matrix3d value;
  };
  // Indices `in` into added_ reordered into `out` by the key (in [0, nodes_)), ties kept
  // in their order in `in`.
  void stable_sort_by(const std::vector<int>& in, std::vector<int>& out, int Entry::*key);

  int nodes_ = 0;
  std::vector<Entry> added_;    // as added
  std::vector<int> order_;      // sort permutation of added_
  std::vector<int> by_column_;  // added_ sorted by column alone (the sort's first pass)
  std::vector<int> bucket_;     // counting sort's cursors, one per node
  std::vector<Entry> upper_;   // merged, sorted by (row, col)
  std::vector<int> row_fill_;  // assembly cursor per row
  Matrix full_;
};

}  // namespace animkit
