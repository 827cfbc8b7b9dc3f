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

/// How the compressed matrix is laid out.
enum class PatternLayout {
  full,       ///< both triangles, rows and columns in particle order (for inspection, tests)
  upper_amd,  ///< only the upper triangle, rows and columns in AMD fill-reducing order: what
              ///< a factorization reads directly, with no reordered copy per factorization
};

/// 3x3 blocks of a 3N x 3N symmetric matrix, one block row and column per particle. Pinned
/// particles are eliminated: their diagonal block is the identity and they have no
/// off-diagonal blocks, so a solve leaves their entries at the right-hand side's (zero) value.
struct HessianPattern {
  SparseMatrix matrix;  ///< compressed; values are rewritten in place
  /// upper_amd: position of DOF i in the matrix's order (empty for full: the identity).
  std::vector<int> order;
  /// Offsets into matrix.valuePtr() of a 3x3 block's entries, column-major (r + 3 c), or -1
  /// where the entry is not stored: the block touches a pinned particle, or (upper_amd) the
  /// entry falls below the diagonal and its mirror image is the one stored.
  using BlockOffsets = std::array<int, 9>;
  std::vector<BlockOffsets> diagonal;                     ///< per particle
  std::vector<std::array<BlockOffsets, 2>> off_diagonal;  ///< per spring: (a,b) and (b,a)

  /// Writes the block Hessian's values into `matrix`.
  void assign(const BlockHessian& blocks);
};

/// Builds the pattern of `model`'s Hessian (all values zero).
HessianPattern build_hessian_pattern(const ClothModel& model,
                                     PatternLayout layout = PatternLayout::full);

}  // namespace animkit
