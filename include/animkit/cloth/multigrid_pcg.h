#pragma once
// Preconditioned conjugate gradients on the block Hessian with a smoothed aggregation
// multigrid V-cycle as preconditioner (Tamstorf, Jones & McCormick, "Smoothed aggregation
// multigrid for cloth simulation", SIGGRAPH Asia 2015). Block Jacobi only damps the error
// between neighbouring particles, so its iteration count grows with the stiffness and the
// resolution; the multigrid hierarchy removes smooth error on coarser and coarser aggregates
// of particles, which keeps the count about constant. Same interface as BlockJacobiPcg.
// The hierarchy's structure is built once per model; each solve redoes only its numeric part.
// No allocation per solve or per iteration; deterministic.
#include <Eigen/Core>
#include <memory>

#include "animkit/cloth/block_hessian.h"
#include "animkit/cloth/preconditioned_cg.h"

namespace animkit {

/// How MultigridPcg builds and applies its smoothed aggregation hierarchy.
struct MultigridOptions {
  int coarsest_nodes = 48;   ///< stop coarsening at or below this many nodes (3 unknowns each)
  int max_levels = 10;       ///< including the finest, >= 1
  int smoothing_sweeps = 1;  ///< block Gauss-Seidel sweeps before and after the coarse correction
  /// Smooth the prolongator with each solve's own matrix instead of, once, with the springs'
  /// isotropic stiffness (see smoothed_aggregation.h).
  bool resmooth = false;
  /// Carry an energy term's blocks between particles the springs do not join (contact) into
  /// every level, so each level is the Galerkin product of the whole Hessian; false: only
  /// their contributions to the diagonal blocks reach the preconditioner.
  bool coarse_couplings = true;
  /// A level of at least twice this many nodes (N) is swept in chunks of N to 2N - 1
  /// consecutive nodes, each a Gauss-Seidel sweep of its own that reads the other chunks'
  /// values from before the sweep (hybrid Gauss-Seidel), so the chunks run on separate threads
  /// with the same bits on any number of threads. 0: one sweep over the whole level.
  int sweep_chunk_nodes = 2048;
};

class SmoothedAggregation;

/// Conjugate gradients preconditioned by a smoothed aggregation multigrid V-cycle.
class MultigridPcg {
 public:
  /// Builds the hierarchy's structure for `model` (kept by reference: it must outlive this).
  explicit MultigridPcg(const ClothModel& model, const MultigridOptions& options = {});
  ~MultigridPcg();

  /// Solves A x = b for the SPD matrix in `a`, from x = 0, until |b - A x| <= tolerance |b|,
  /// `max_iterations`, or a direction of non-positive curvature (see PcgResult). The energy
  /// terms' blocks (`a.extra`) are taken anew only under a new BlockHessian::terms_revision:
  /// under the last solve's, those of that solve are used.
  PcgResult solve(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                  double tolerance, int max_iterations);
  /// Refines the last solve's answer x of A x = b to the tighter `tolerance`, going on from x
  /// with the hierarchy that solve built: `a` and `b` must be the same as then.
  PcgResult refine(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   double tolerance, int max_iterations);

  /// The hierarchy's number of levels (1: no coarsening).
  int level_count() const;
  /// The number of nodes on `level` (0: the particles), 0 <= level < level_count().
  int level_nodes(int level) const;
  /// The number of 3x3 blocks in `level`'s pattern (energy terms' couplings aside).
  int level_blocks(int level) const;

  /// z = B r with the preconditioner set up by the last solve (for tests).
  void apply_preconditioner(const Eigen::VectorXd& r, Eigen::VectorXd& z);

 private:
  PcgResult iterate(const BlockHessian& a, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    double tolerance, int max_iterations, CgStart start);

  const ClothModel& model_;
  std::unique_ptr<SmoothedAggregation> multigrid_;
  CgWorkspace workspace_;
};

}  // namespace animkit
