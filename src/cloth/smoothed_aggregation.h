#pragma once
// Smoothed aggregation multigrid on 3x3 blocks as a preconditioner for the implicit step's
// Hessian (Tamstorf, Jones & McCormick, "Smoothed aggregation multigrid for cloth
// simulation", SIGGRAPH Asia 2015; after Vanek, Mandel & Brezina 1996).
//
// Structure, once per model: the finest level's pattern comes from the spring graph, nodes
// are aggregated (aggregation.h), the tentative prolongator T maps each aggregate's 3 coarse
// unknowns to its particles (the near-null space: the three translations, orthonormalized per
// aggregate), P = (I - omega D^-1 A) T smooths it, and P^T A P gives the next level, down to a
// level small enough for a dense Cholesky factorization. Smoothing P with the matrix of the
// model's springs (k I per spring, see laplacian()) at construction makes P, every pattern and
// every Galerkin plan fixed per model: a solve only copies the Hessian in, recomputes the
// Galerkin products and factorizes the coarsest level. `resmooth` instead smooths P with each
// solve's own matrix (anisotropic spring blocks), at the cost of a power iteration and the
// smoothing per level.
//
// A bend's coupling between the two ends of its line (a spring of stiffness 0 in the model)
// stays out of the finest pattern: its block E is lumped onto both ends' diagonal blocks as
// |E| I, which keeps the preconditioner's matrix SPD (and, with the bends far softer than the
// membrane, about as good). The finest level loses a third of its blocks (a grid's rows 13 to
// 9), and the coarser ones follow: each CG iteration is cheaper.
//
// An energy term's blocks between particles the springs do not join (contact) change pattern
// from solve to solve: they ride beside each level's fixed pattern (coupling_blocks.h), so
// every level is still the Galerkin product of the whole Hessian.
//
// One application is a V-cycle with a forward block Gauss-Seidel sweep before the coarse
// correction and a backward one after it: the cycle is then a symmetric positive definite
// operator, as CG needs. After a single forward sweep from zero, the residual it passes down
// needs only the diagonal and upper triangle (residual_after_sweep).
//
// A large level is swept in chunks of consecutive nodes over the threads (hybrid Gauss-Seidel):
// Gauss-Seidel within a chunk, the other chunks' values from before the sweep. The chunks depend
// on the level's size alone, so the bits do not depend on the thread count. Each coupling B across
// chunks adds half of (B B^T)^(1/2) to its row's diagonal block, a variant of the l1 smoother of
// Baker, Falgout, Kolev & Yang ("Multigrid smoothers for ultraparallel computing", SIAM J. Sci.
// Comput. 2011, which adds the off-processor row sums |a_ij|): M + M^T - A is then the diagonal
// plus a PSD matrix per coupling, so the sweep converges and, with the backward sweep its
// transpose, the cycle is SPD.
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <vector>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/cloth_model.h"
#include "animkit/cloth/multigrid_pcg.h"
#include "block_sparse_matrix.h"
#include "coupling_blocks.h"
#include "galerkin_product.h"

namespace animkit {

class SmoothedAggregation {
 public:
  using Matrix = BlockSparseMatrix<3, 3>;

  SmoothedAggregation(const ClothModel& model, const MultigridOptions& options = {});

  /// Numeric setup for the matrix `a` (the model's, see BlockHessian): Galerkin products,
  /// smoother blocks, coarsest factorization. Allocates nothing. False when the coarsest
  /// level is not positive definite (then `a` is not: P has full column rank).
  bool update(const BlockHessian& a);
  /// z = B r, one V-cycle; B approximates A^-1 and is symmetric positive definite.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& z);
  /// y += E x for the energy terms' blocks E of the last update()'s matrix, assembled: their
  /// diagonal blocks summed per particle, their couplings merged into rows (one block per pair
  /// of particles). With BlockHessian::multiply_without_terms, the same product as
  /// BlockHessian::multiply, without its scattered addition of every term block.
  void add_term_products(const Eigen::VectorXd& x, Eigen::VectorXd& y) const;

  int level_count() const { return static_cast<int>(levels_.size()); }
  /// Nodes (3 unknowns each) on level l (0: the particles).
  int level_nodes(int l) const { return levels_[l].a.block_rows; }
  int level_blocks(int l) const { return levels_[l].a.block_count(); }

 private:
  struct Level {
    Matrix a;                   // this level's operator (both triangles)
    CouplingBlocks coupling;    // plus these blocks outside a's pattern (contact, see there)
    // The finer level's couplings restricted into this level's diagonal blocks (not on the
    // finest level): added into `a` after each Galerkin product.
    std::vector<CouplingBlocks::DiagonalPart> coupling_within;
    std::vector<int> diagonal;  // position of each row's diagonal block
    std::vector<Eigen::Matrix3d> inverse_diagonal;
    // Hybrid sweeps (chunk_start holds more than one chunk): chunk c is the nodes
    // [chunk_start[c], chunk_start[c + 1]); its sweep applies sweep_inverse (the diagonal
    // blocks with the l1 term, inverted) and reads other chunks from x_before.
    std::vector<int> chunk_start;
    std::vector<int> chunk_of;  // per node
    std::vector<Eigen::Matrix3d> sweep_inverse;
    Eigen::VectorXd x_before;
    bool in_chunks() const { return chunk_start.size() > 2; }
    // Towards the next level (absent on the coarsest):
    std::vector<int> aggregate;              // per node, -1 when excluded (pinned)
    std::vector<Eigen::Matrix3d> tentative;  // T's block per node
    Matrix p;                                // smoothed prolongator
    std::vector<double> p_scale;  // P's blocks as multiples of I (see scalar_blocks), or empty
    std::vector<int> smooth_target;          // per block of `a`: P block it smooths into
    GalerkinProduct<3, 3> galerkin;
    Eigen::VectorXd b, x, r;
  };

  // keep_terms: the terms' blocks are those of the last fill (their part is kept).
  void fill_finest(const BlockHessian& a, bool keep_terms);
  void fill_laplacian();
  void prepare_smoother(Level& level);
  void smooth_prolongator(Level& level);
  bool factorize_coarsest();
  // The level's couplings the V-cycle uses (MultigridOptions::coarse_couplings), or none.
  const Matrix* couplings(const Level& level) const;
  // from_zero: level.x is zero, so only the columns before each row carry values (the later
  // ones are still zero and would add nothing): half the products of a sweep. In chunks
  // (Level::in_chunks()), the columns before each row within its own chunk.
  void forward_sweep(Level& level, bool from_zero);
  void backward_sweep(Level& level);
  void forward_sweep_chunked(Level& level, bool from_zero);
  void backward_sweep_chunked(Level& level);
  // sweep_inverse: the diagonal blocks with the l1 term of the blocks across chunks, inverted.
  void prepare_chunked_smoother(Level& level);
  // Node i of a hybrid sweep: x_i += S_i^-1 (b - A x)_i, where `rest` is b_i less the row's
  // products off the diagonal and S_i the diagonal block with the l1 term.
  void relax_row(Level& level, int i, const Eigen::Vector3d& rest, bool from_zero);
  // r = b - A x after a single forward sweep from zero, which left (b - L x)_i in r: the
  // diagonal and upper triangle remain, about half a product. In chunks, L is the lower
  // triangle within each chunk, and the earlier chunks' columns remain too.
  void residual_after_sweep(Level& level);
  void residual_after_chunked_sweep(Level& level);
  void cycle(std::size_t l);

  const ClothModel& model_;
  MultigridOptions options_;
  std::vector<Level> levels_;
  std::vector<Eigen::Matrix3d> term_diagonal_;  // the terms' diagonal blocks, per particle
  bool has_terms_ = false;
  std::uint64_t terms_revision_ = 0;  // BlockHessian::terms_revision of the last update
  std::vector<std::array<int, 2>> spring_blocks_;  // per spring: positions of (a,b), (b,a)
  std::vector<int> lumped_springs_;  // the bends' coupling springs between free particles
  Eigen::MatrixXd coarsest_dense_;
  Eigen::LLT<Eigen::MatrixXd> coarsest_;
  Eigen::VectorXd power_x_, power_y_;  // power iteration workspace (finest size)
};

}  // namespace animkit
