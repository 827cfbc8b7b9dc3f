#include "smoothed_aggregation.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

#include "../core/parallel.h"
#include "aggregation.h"

namespace animkit {

namespace {

using Matrix3 = Eigen::Matrix3d;

std::vector<int> diagonal_positions(const BlockSparseMatrix<3, 3>& a) {
  std::vector<int> positions(static_cast<std::size_t>(a.block_rows));
  for (int i = 0; i < a.block_rows; ++i) positions[i] = a.find(i, i);
  return positions;
}

// The block inverse of a diagonal block, which is SPD for the cloth's matrices (M / h^2 plus
// PSD spring blocks). A singular block (a node without unknowns) is left alone (identity).
Matrix3 inverse_block(const Matrix3& block) {
  Matrix3 inverse;
  bool invertible = false;
  block.computeInverseWithCheck(inverse, invertible);
  return invertible ? inverse : Matrix3::Identity();
}

// (B B^T)^(1/2): with (B^T B)^(1/2) for the transposed block in the other row, [(B B^T)^(1/2),
// -B; -B^T, (B^T B)^(1/2)] is positive semidefinite (polar decomposition), so half of it on
// each end of every coupling across chunks keeps a hybrid sweep convergent: the sweep's
// M + M^T - A is then the diagonal plus those PSD matrices (for a spring's symmetric block K
// it is |K|, which adds nothing transverse to the spring, where the cloth is soft).
Matrix3 block_magnitude(const Matrix3& block) {
  Eigen::SelfAdjointEigenSolver<Matrix3> eigen;
  eigen.computeDirect(block * block.transpose());
  const Eigen::Vector3d root = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return eigen.eigenvectors() * root.asDiagonal() * eigen.eigenvectors().transpose();
}

// Each block's c when every block of p is exactly c I; empty otherwise.
std::vector<double> scalar_blocks(const BlockSparseMatrix<3, 3>& p) {
  std::vector<double> scale;
  scale.reserve(p.values.size());
  for (const Matrix3& block : p.values) {
    if (block != block(0, 0) * Matrix3::Identity()) return {};
    scale.push_back(block(0, 0));
  }
  return scale;
}

}  // namespace

SmoothedAggregation::SmoothedAggregation(const ClothModel& model, const MultigridOptions& options)
    : model_(model), options_(options) {
  const int n = model.particle_count();
  // Finest pattern: a particle's block row holds itself and the free particles it shares a
  // spring with, but for the bends' coupling springs (lumped_springs_); pinned rows hold only
  // their (identity) diagonal.
  std::vector<std::vector<int>> rows(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) rows[i].push_back(i);
  for (std::size_t s = 0; s < model.springs.size(); ++s) {
    const auto [a, b] = model.springs[s];
    if (model.pinned[a] || model.pinned[b]) continue;
    if (model.stiffness[s] == 0.0) {
      lumped_springs_.push_back(static_cast<int>(s));
      continue;
    }
    rows[a].push_back(b);
    rows[b].push_back(a);
  }
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
  }
  levels_.emplace_back();
  levels_[0].a = block_pattern<3, 3>(rows, n);
  spring_blocks_.reserve(model.springs.size());
  for (std::size_t s = 0; s < model.springs.size(); ++s) {
    const auto [a, b] = model.springs[s];
    const bool kept = !model.pinned[a] && !model.pinned[b] && model.stiffness[s] != 0.0;
    spring_blocks_.push_back(
        {kept ? levels_[0].a.find(a, b) : -1, kept ? levels_[0].a.find(b, a) : -1});
  }

  // Levels: aggregate, build T from the near-null space, then P's pattern and the next level.
  std::vector<Matrix3> null_space(static_cast<std::size_t>(n), Matrix3::Identity());
  std::vector<char> excluded(model.pinned.begin(), model.pinned.end());
  while (static_cast<int>(levels_.size()) < options_.max_levels &&
         levels_.back().a.block_rows > options_.coarsest_nodes) {
    Level& level = levels_.back();
    const int nodes = level.a.block_rows;
    const Aggregates aggregates = aggregate_graph(level.a.row_start, level.a.column, excluded);
    if (aggregates.count == 0 || aggregates.count >= nodes) break;  // no coarsening possible
    level.aggregate = aggregates.of_node;
    // T restricted to an aggregate is its null-space blocks B_i orthonormalized together:
    // T_i = B_i R^-1 with R^T R = sum B_i^T B_i (Cholesky QR); R is the aggregate's null
    // space on the next level (Vanek et al. 1996, section 3).
    std::vector<Matrix3> gram(static_cast<std::size_t>(aggregates.count), Matrix3::Zero());
    for (int i = 0; i < nodes; ++i) {
      if (level.aggregate[i] >= 0)
        gram[level.aggregate[i]] += null_space[i].transpose() * null_space[i];
    }
    std::vector<Matrix3> r_factor(gram.size());
    for (std::size_t c = 0; c < gram.size(); ++c) r_factor[c] = gram[c].llt().matrixU();
    level.tentative.assign(static_cast<std::size_t>(nodes), Matrix3::Zero());
    for (int i = 0; i < nodes; ++i) {
      const int c = level.aggregate[i];
      if (c < 0) continue;
      level.tentative[i] =
          r_factor[c].triangularView<Eigen::Upper>().solve<Eigen::OnTheRight>(null_space[i]);
    }
    // P = (I - omega D^-1 A) T: row i reaches the aggregates of i and of its neighbours.
    std::vector<std::vector<int>> p_rows(static_cast<std::size_t>(nodes));
    for (int i = 0; i < nodes; ++i) {
      if (level.aggregate[i] < 0) continue;
      for (int k = level.a.row_start[i]; k < level.a.row_start[i + 1]; ++k) {
        const int c = level.aggregate[level.a.column[k]];
        if (c >= 0) p_rows[i].push_back(c);
      }
      std::sort(p_rows[i].begin(), p_rows[i].end());
      p_rows[i].erase(std::unique(p_rows[i].begin(), p_rows[i].end()), p_rows[i].end());
    }
    level.p = block_pattern<3, 3>(p_rows, aggregates.count);
    level.smooth_target.assign(level.a.column.size(), -1);
    for (int i = 0; i < nodes; ++i) {
      if (level.aggregate[i] < 0) continue;
      for (int k = level.a.row_start[i]; k < level.a.row_start[i + 1]; ++k) {
        const int c = level.aggregate[level.a.column[k]];
        if (c >= 0) level.smooth_target[k] = level.p.find(i, c);
      }
    }
    Level next;
    next.a = level.galerkin.analyze(level.a, level.p);
    levels_.push_back(std::move(next));
    null_space = std::move(r_factor);
    excluded.assign(static_cast<std::size_t>(aggregates.count), 0);
  }
  for (Level& level : levels_) {
    level.diagonal = diagonal_positions(level.a);
    level.inverse_diagonal.resize(static_cast<std::size_t>(level.a.block_rows));
    const auto size = 3 * static_cast<Eigen::Index>(level.a.block_rows);
    level.b.setZero(size);
    level.x.setZero(size);
    level.r.setZero(size);
    level.coupling.clear(level.a.block_rows);
    level.coupling.assemble();
    // Hybrid sweeps from twice the chunk size on: chunks as equal as the count allows (the
    // coarsest level is solved directly, never swept).
    const int nodes = level.a.block_rows;
    const int chunks = options_.sweep_chunk_nodes > 0 && &level != &levels_.back()
                           ? nodes / options_.sweep_chunk_nodes
                           : 0;
    if (chunks >= 2) {
      for (int c = 0; c <= chunks; ++c)
        level.chunk_start.push_back(static_cast<int>(std::int64_t{nodes} * c / chunks));
      level.chunk_of.resize(static_cast<std::size_t>(nodes));
      for (int c = 0; c < chunks; ++c) {
        for (int i = level.chunk_start[c]; i < level.chunk_start[c + 1]; ++i) level.chunk_of[i] = c;
      }
      level.sweep_inverse.resize(static_cast<std::size_t>(nodes));
      level.x_before.setZero(size);
    }
  }
  const auto coarse_size = 3 * static_cast<Eigen::Index>(levels_.back().a.block_rows);
  coarsest_dense_.setZero(coarse_size, coarse_size);
  coarsest_.compute(Eigen::MatrixXd::Identity(coarse_size, coarse_size));

  if (!options_.resmooth) {
    // P for good, from the model's springs alone. Its blocks are then multiples of the
    // identity: T's are (the near-null space is the translations, I per node, and on coarser
    // levels R = sqrt(size) I of each aggregate), and so are the Laplacian's blocks k I, hence
    // D^-1 A's on every level. Each solve's Galerkin products then scale blocks instead of
    // multiplying them (GalerkinProduct::compute).
    fill_laplacian();
    for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
      prepare_smoother(levels_[l]);
      smooth_prolongator(levels_[l]);
      levels_[l].p_scale = scalar_blocks(levels_[l].p);
      levels_[l].galerkin.compute(levels_[l].a, levels_[l].p, levels_[l + 1].a);
    }
  }
}

void SmoothedAggregation::fill_laplacian() {
  // sum over springs of k (e_a - e_b)(e_a - e_b)^T (x) I: the isotropic stiffness of the
  // springs, what the cloth's matrix tends to once springs dominate the inertia.
  Matrix& a = levels_[0].a;
  for (auto& block : a.values) block.setZero();
  for (std::size_t s = 0; s < model_.springs.size(); ++s) {
    const auto [i, j] = model_.springs[s];
    const Matrix3 k = model_.stiffness[s] * Matrix3::Identity();
    if (!model_.pinned[i]) a.values[levels_[0].diagonal[i]] += k;
    if (!model_.pinned[j]) a.values[levels_[0].diagonal[j]] += k;
    if (spring_blocks_[s][0] >= 0) {
      a.values[spring_blocks_[s][0]] -= k;
      a.values[spring_blocks_[s][1]] -= k;
    }
  }
  for (int i = 0; i < a.block_rows; ++i) {
    Matrix3& d = a.values[levels_[0].diagonal[i]];
    if (model_.pinned[i] || d(0, 0) == 0.0) d = Matrix3::Identity();
  }
}

void SmoothedAggregation::fill_finest(const BlockHessian& hessian, bool keep_terms) {
  Matrix& a = levels_[0].a;
  // Each particle's row and each spring's two blocks are written once: over the threads.
  parallel::for_each(a.block_rows, [&](int i) {
    for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) a.values[k].setZero();
    a.values[levels_[0].diagonal[i]] = hessian.diagonal[i];
  });
  parallel::for_each(static_cast<int>(spring_blocks_.size()), [&](int s) {
    const auto& [ab, ba] = spring_blocks_[static_cast<std::size_t>(s)];
    if (ab < 0) return;
    const Matrix3& k = hessian.coupling[static_cast<std::size_t>(s)];
    a.values[ab] = Matrix3::Zero() - k;  // 0 - k, as the sums always made it (no -0.0)
    a.values[ba] = Matrix3::Zero() - k;
  });
  // A lumped spring's coupling E leaves the pattern and |E| I joins both diagonal blocks:
  // [|E| I, -E; -E^T, |E| I] is PSD when |E| bounds E's spectral norm (the infinity norm of
  // a symmetric block does), so the preconditioner's matrix stays SPD and only gains.
  for (const int s : lumped_springs_) {
    const auto [i, j] = model_.springs[static_cast<std::size_t>(s)];
    const double bound = hessian.coupling[static_cast<std::size_t>(s)]
                             .cwiseAbs()
                             .rowwise()
                             .sum()
                             .maxCoeff();
    a.values[levels_[0].diagonal[i]].diagonal().array() += bound;
    a.values[levels_[0].diagonal[j]].diagonal().array() += bound;
  }
  // The terms' diagonal blocks are in hessian.diagonal already; their couplings go beside
  // (add_term_products always uses them; the V-cycle with coarse_couplings).
  if (keep_terms) return;
  CouplingBlocks& coupling = levels_[0].coupling;
  coupling.clear(a.block_rows);
  term_diagonal_.assign(static_cast<std::size_t>(a.block_rows), Matrix3::Zero());
  for (const HessianBlock& block : hessian.extra) {
    if (block.row != block.col) {
      coupling.add(block.row, block.col, block.value);
    } else {
      term_diagonal_[static_cast<std::size_t>(block.row)] += block.value;
    }
  }
  coupling.assemble();
  has_terms_ = !hessian.extra.empty();
}

void SmoothedAggregation::prepare_smoother(Level& level) {
  parallel::for_each(level.a.block_rows, [&](int i) {
    level.inverse_diagonal[i] = inverse_block(level.a.values[level.diagonal[i]]);
  });
}

void SmoothedAggregation::smooth_prolongator(Level& level) {
  // omega = 4 / (3 rho(D^-1 A)) (Vanek et al. 1996), rho from a few power iterations started
  // from a fixed vector, so the result is reproducible.
  Eigen::VectorXd& v = level.x;
  Eigen::VectorXd& w = level.r;
  for (Eigen::Index k = 0; k < v.size(); ++k) v[k] = 1.0 + 0.25 * static_cast<double>(k % 7);
  double rho = 1.0;
  for (int it = 0; it < 12; ++it) {
    v /= v.norm();
    level.a.multiply(v, w);
    for (int i = 0; i < level.a.block_rows; ++i)
      v.segment<3>(3 * i) = level.inverse_diagonal[i] * w.segment<3>(3 * i);
    rho = v.norm();
  }
  const double omega = 4.0 / (3.0 * rho);
  for (auto& block : level.p.values) block.setZero();
  for (int i = 0; i < level.a.block_rows; ++i) {
    if (level.aggregate[i] < 0) continue;
    level.p.values[level.p.find(i, level.aggregate[i])] += level.tentative[i];
    const Matrix3 scaled = omega * level.inverse_diagonal[i];
    for (int k = level.a.row_start[i]; k < level.a.row_start[i + 1]; ++k) {
      if (level.smooth_target[k] < 0) continue;
      level.p.values[level.smooth_target[k]].noalias() -=
          scaled * (level.a.values[k] * level.tentative[level.a.column[k]]);
    }
  }
}

bool SmoothedAggregation::factorize_coarsest() {
  const Level& level = levels_.back();
  coarsest_dense_.setZero();
  for (int i = 0; i < level.a.block_rows; ++i) {
    for (int k = level.a.row_start[i]; k < level.a.row_start[i + 1]; ++k)
      coarsest_dense_.block<3, 3>(3 * i, 3 * level.a.column[k]) = level.a.values[k];
  }
  const Matrix& e = level.coupling.full();
  for (int i = 0; i < e.block_rows; ++i) {
    for (int k = e.row_start[i]; k < e.row_start[i + 1]; ++k)
      coarsest_dense_.block<3, 3>(3 * i, 3 * e.column[k]) += e.values[k];
  }
  coarsest_.compute(coarsest_dense_);
  return coarsest_.info() == Eigen::Success;
}

bool SmoothedAggregation::update(const BlockHessian& hessian) {
  // The terms' blocks of the last update again (Newton's projected retry redoes the springs'
  // alone): their couplings on every level are kept, the sums they join redone in the same
  // order. On drape-sphere 41 x 41 their sorting and restriction took 8% of the run, and two
  // updates in five are retries. A P smoothed with each matrix (resmooth) restricts anew.
  // Kept means kept for the products too (add_term_products): see BlockHessian::terms_revision.
  const bool keep_terms = hessian.terms_revision != 0 &&
                          hessian.terms_revision == terms_revision_ && !options_.resmooth;
  terms_revision_ = hessian.terms_revision;
  fill_finest(hessian, keep_terms);
  for (std::size_t l = 0; l + 1 < levels_.size(); ++l) {
    Level& coarse = levels_[l + 1];
    // A chunked level's sweeps use sweep_inverse (its couplings are final here): the plain
    // inverses only where the sweeps or the prolongator's smoothing need them.
    if (levels_[l].in_chunks()) prepare_chunked_smoother(levels_[l]);
    if (!levels_[l].in_chunks() || options_.resmooth) prepare_smoother(levels_[l]);
    if (options_.resmooth) smooth_prolongator(levels_[l]);
    levels_[l].galerkin.compute(levels_[l].a, levels_[l].p, coarse.a,
                                levels_[l].p_scale.empty() ? nullptr : &levels_[l].p_scale);
    if (options_.coarse_couplings) {
      if (!keep_terms)
        levels_[l].coupling.restrict_to(levels_[l].p, coarse.coupling, coarse.coupling_within);
      CouplingBlocks::add_within(coarse.coupling_within, coarse.a, coarse.diagonal);
    }
  }
  prepare_smoother(levels_.back());
  return factorize_coarsest();
}

const SmoothedAggregation::Matrix* SmoothedAggregation::couplings(const Level& level) const {
  // Without coarse_couplings only the diagonal blocks of the terms' Hessians reach the
  // preconditioner (the finest level's couplings are then there for add_term_products alone).
  return options_.coarse_couplings ? &level.coupling.full() : nullptr;
}

void SmoothedAggregation::prepare_chunked_smoother(Level& level) {
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  parallel::for_each(a.block_rows, [&](int i) {
    Matrix3 diagonal = a.values[level.diagonal[i]];
    const auto add_across = [&](int j, const Matrix3& block) {
      if (level.chunk_of[j] != level.chunk_of[i]) diagonal += 0.5 * block_magnitude(block);
    };
    for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) add_across(a.column[k], a.values[k]);
    if (e != nullptr) {
      for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k)
        add_across(e->column[k], e->values[k]);
    }
    level.sweep_inverse[i] = inverse_block(diagonal);
  });
}

void SmoothedAggregation::cycle(std::size_t l) {
  Level& level = levels_[l];
  if (l + 1 == levels_.size()) {
    level.x = level.b;
    coarsest_.solveInPlace(level.x);
    return;
  }
  level.x.setZero();
  for (int s = 0; s < options_.smoothing_sweeps; ++s) forward_sweep(level, s == 0);
  if (options_.smoothing_sweeps == 1) {
    residual_after_sweep(level);
  } else {
    level.a.multiply(level.x, level.r);
    if (const Matrix* e = couplings(level)) e->multiply_add(level.x, level.r);
    level.r = level.b - level.r;
  }
  Level& next = levels_[l + 1];
  level.p.multiply_transpose(level.r, next.b);
  cycle(l + 1);
  // x += P x_next, row by row over the threads (each row its own sum: the same bits).
  parallel::for_each(level.p.block_rows, [&](int i) {
    for (int k = level.p.row_start[i]; k < level.p.row_start[i + 1]; ++k)
      level.x.segment<3>(3 * i).noalias() +=
          level.p.values[k] * next.x.segment<3>(3 * level.p.column[k]);
  });
  for (int s = 0; s < options_.smoothing_sweeps; ++s) backward_sweep(level);
}

void SmoothedAggregation::add_term_products(const Eigen::VectorXd& x, Eigen::VectorXd& y) const {
  if (!has_terms_) return;
  const Matrix& e = levels_[0].coupling.full();
  parallel::for_each(e.block_rows, [&](int i) {
    Eigen::Vector3d sum = term_diagonal_[static_cast<std::size_t>(i)] * x.segment<3>(3 * i);
    for (int k = e.row_start[i]; k < e.row_start[i + 1]; ++k)
      sum.noalias() += e.values[k] * x.segment<3>(3 * e.column[k]);
    y.segment<3>(3 * i) += sum;
  });
}

void SmoothedAggregation::apply(const Eigen::VectorXd& r, Eigen::VectorXd& z) {
  levels_[0].b = r;
  cycle(0);
  z = levels_[0].x;
}

}  // namespace animkit
