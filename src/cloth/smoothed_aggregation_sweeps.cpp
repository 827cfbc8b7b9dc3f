// The smoother of the V-cycle (smoothed_aggregation.h): block Gauss-Seidel sweeps, whole or in
// chunks over the threads (hybrid), and the residual a single forward sweep leaves.
#include "../core/parallel.h"
#include "smoothed_aggregation.h"

namespace animkit {

// The residual form, since S_i (the diagonal with the l1 term) is not A's diagonal block:
// written as x_i = S_i^-1 rest, the sweep would converge to the solution of another system.
void SmoothedAggregation::relax_row(Level& level, int i, const Eigen::Vector3d& rest,
                                    bool from_zero) {
  auto x = level.x.segment<3>(3 * i);
  if (from_zero) {
    x.noalias() = level.sweep_inverse[i] * rest;
  } else {
    const Eigen::Vector3d residual = rest - level.a.values[level.diagonal[i]] * x;
    x.noalias() += level.sweep_inverse[i] * residual;
  }
}

// Chunk by chunk over the threads, Gauss-Seidel within each; a column in another chunk takes
// its value from before the sweep (zero from zero), so no chunk reads what another writes.
// The couplings (an energy term's blocks off the pattern) are part of each row like a's own.
void SmoothedAggregation::forward_sweep_chunked(Level& level, bool from_zero) {
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  if (!from_zero) level.x_before = level.x;
  const int chunks = static_cast<int>(level.chunk_start.size()) - 1;
  parallel::run_tasks(chunks, thread_count(), [&](int c) {
    const int first = level.chunk_start[c], end = level.chunk_start[c + 1];
    for (int i = first; i < end; ++i) {
      Eigen::Vector3d sum = level.b.segment<3>(3 * i);
      const auto subtract = [&](int j, const Eigen::Matrix3d& block) {
        if (j >= first && j < end) {
          if (!from_zero || j < i) sum.noalias() -= block * level.x.segment<3>(3 * j);
        } else if (!from_zero) {
          sum.noalias() -= block * level.x_before.segment<3>(3 * j);
        }
      };
      for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
        if (k != level.diagonal[i]) subtract(a.column[k], a.values[k]);
      }
      if (e != nullptr) {
        for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k)
          subtract(e->column[k], e->values[k]);
      }
      level.r.segment<3>(3 * i) = sum;  // for residual_after_sweep
      relax_row(level, i, sum, from_zero);
    }
  });
}

void SmoothedAggregation::backward_sweep_chunked(Level& level) {
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  level.x_before = level.x;
  const int chunks = static_cast<int>(level.chunk_start.size()) - 1;
  parallel::run_tasks(chunks, thread_count(), [&](int c) {
    const int first = level.chunk_start[c], end = level.chunk_start[c + 1];
    for (int i = end - 1; i >= first; --i) {
      Eigen::Vector3d sum = level.b.segment<3>(3 * i);
      const auto subtract = [&](int j, const Eigen::Matrix3d& block) {
        const bool inside = j >= first && j < end;
        sum.noalias() -= block * (inside ? level.x : level.x_before).segment<3>(3 * j);
      };
      for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
        if (k != level.diagonal[i]) subtract(a.column[k], a.values[k]);
      }
      if (e != nullptr) {
        for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k)
          subtract(e->column[k], e->values[k]);
      }
      relax_row(level, i, sum, false);
    }
  });
}

// After a chunked forward sweep from zero, r_i holds b_i less the columns before i in i's own
// chunk: every other column is left, the earlier chunks' included.
void SmoothedAggregation::residual_after_chunked_sweep(Level& level) {
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  parallel::for_each(a.block_rows, [&](int i) {
    const int first = level.chunk_start[level.chunk_of[i]];
    Eigen::Vector3d sum = level.r.segment<3>(3 * i);
    for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      const int j = a.column[k];
      if (j < first || j >= i) sum.noalias() -= a.values[k] * level.x.segment<3>(3 * j);
    }
    if (e != nullptr) {
      for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k) {
        const int j = e->column[k];
        if (j < first || j >= i) sum.noalias() -= e->values[k] * level.x.segment<3>(3 * j);
      }
    }
    level.r.segment<3>(3 * i) = sum;
  });
}

void SmoothedAggregation::forward_sweep(Level& level, bool from_zero) {
  if (level.in_chunks()) return forward_sweep_chunked(level, from_zero);
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  for (int i = 0; i < a.block_rows; ++i) {
    const int end = from_zero ? i : a.block_rows;  // columns from `end` on hold zeros
    Eigen::Vector3d sum = level.b.segment<3>(3 * i);
    for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      if (k != level.diagonal[i] && a.column[k] < end)
        sum.noalias() -= a.values[k] * level.x.segment<3>(3 * a.column[k]);
    }
    if (e != nullptr) {
      for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k) {
        if (e->column[k] < end)
          sum.noalias() -= e->values[k] * level.x.segment<3>(3 * e->column[k]);
      }
    }
    level.r.segment<3>(3 * i) = sum;  // b_i - (L x)_i, for residual_after_sweep
    level.x.segment<3>(3 * i).noalias() = level.inverse_diagonal[i] * sum;
  }
}

void SmoothedAggregation::backward_sweep(Level& level) {
  if (level.in_chunks()) return backward_sweep_chunked(level);
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  for (int i = a.block_rows - 1; i >= 0; --i) {
    Eigen::Vector3d sum = level.b.segment<3>(3 * i);
    for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
      if (k != level.diagonal[i])
        sum.noalias() -= a.values[k] * level.x.segment<3>(3 * a.column[k]);
    }
    if (e != nullptr) {
      for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k)
        sum.noalias() -= e->values[k] * level.x.segment<3>(3 * e->column[k]);
    }
    level.x.segment<3>(3 * i).noalias() = level.inverse_diagonal[i] * sum;
  }
}

void SmoothedAggregation::residual_after_sweep(Level& level) {
  if (level.in_chunks()) return residual_after_chunked_sweep(level);
  // r_i = (b - L x)_i - D_i x_i - (U x)_i, the first term kept by the sweep. D_i x_i is not
  // dropped as equal to (b - L x)_i, which the sweep solved for: only exact arithmetic makes
  // it so, and with a contact barrier's ill-conditioned diagonal blocks that version left a
  // step of a ball pushed into a hanging sheet at Newton's cap (moving_obstacles_test.cpp).
  // A row's columns are sorted, so the ones after its diagonal block are those after i; the
  // couplings have no diagonal block.
  const Matrix& a = level.a;
  const Matrix* e = couplings(level);
  parallel::for_each(a.block_rows, [&](int i) {  // rows apart: the same bits on any threads
    Eigen::Vector3d sum = level.r.segment<3>(3 * i);
    sum.noalias() -= a.values[level.diagonal[i]] * level.x.segment<3>(3 * i);
    for (int k = level.diagonal[i] + 1; k < a.row_start[i + 1]; ++k)
      sum.noalias() -= a.values[k] * level.x.segment<3>(3 * a.column[k]);
    if (e != nullptr) {
      for (int k = e->row_start[i]; k < e->row_start[i + 1]; ++k) {
        if (e->column[k] > i) sum.noalias() -= e->values[k] * level.x.segment<3>(3 * e->column[k]);
      }
    }
    level.r.segment<3>(3 * i) = sum;
  });
}

}  // namespace animkit
