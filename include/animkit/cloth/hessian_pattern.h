#pragma once
// The implicit step's Hessian as a compressed sparse matrix, for the direct solver. The
// sparsity pattern is built once per model; each Newton iteration then writes the block
// Hessian's values straight into it through precomputed offsets: no triplets, no re-sorting,
// and the direct solver's symbolic analysis done once.
#include <Eigen/SparseCore>
#include <array>
#include <vector>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/cloth_model.h"

namespace animkit {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// 3x3 blocks of a 3N x 3N symmetric matrix (both triangles stored), one block row and column
/// per particle. Pinned particles are eliminated: their diagonal block is the identity and
/// they have no off-diagonal blocks, so a solve leaves their entries at the right-hand side's
/// (zero) value.
struct HessianPattern {
  SparseMatrix matrix;  ///< compressed; values are rewritten in place
  /// Offsets into matrix.valuePtr() of a 3x3 block's entries, column-major (r + 3 c), or -1
  /// for every entry when the block is not stored (it touches a pinned particle).
  using BlockOffsets = std::array<int, 9>;
  std::vector<BlockOffsets> diagonal;                     ///< per particle
  std::vector<std::array<BlockOffsets, 2>> off_diagonal;  ///< per spring: (a,b) and (b,a)

  /// Writes the block Hessian's values into `matrix`.
  void assign(const BlockHessian& blocks);
};

/// Builds the pattern of `model`'s Hessian (all values zero).
HessianPattern build_hessian_pattern(const ClothModel& model);

}  // namespace animkit
