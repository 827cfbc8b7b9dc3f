#pragma once
// The Galerkin coarse operator A_c = P^T A P of smoothed aggregation multigrid, for block
// matrices whose patterns never change. analyze() works out every pattern and lists, once,
// which block products add into which output block; compute() then replays that list on new
// values: no searching, no allocation, and always the same order of sums (same bits).
// A is symmetric, so only the upper block triangle of A_c is summed and the lower one mirrored.
// The products of one output row are listed together, so rows run in parallel with each block
// still summed in the same order: the same bits with any number of threads.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../core/parallel.h"
#include "block_sparse_matrix.h"

namespace animkit {

template <int F, int C>
class GalerkinProduct {
 public:
  /// Plans P^T A P for these patterns and returns the coarse pattern (values zero).
  BlockSparseMatrix<C, C> analyze(const BlockSparseMatrix<F, F>& a,
                                  const BlockSparseMatrix<F, C>& p) {
    const int fine = a.block_rows, coarse = p.block_cols;
    std::vector<int> slot(static_cast<std::size_t>(coarse), -1);
    // A P, row by row: the union of P's rows over A's columns.
    std::vector<std::vector<int>> rows(static_cast<std::size_t>(fine));
    for (int i = 0; i < fine; ++i) {
      for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
        const int j = a.column[k];
        for (int q = p.row_start[j]; q < p.row_start[j + 1]; ++q) {
          if (slot[p.column[q]] < 0) {
            slot[p.column[q]] = 0;
            rows[i].push_back(p.column[q]);
          }
        }
      }
      std::sort(rows[i].begin(), rows[i].end());
      for (int c : rows[i]) slot[c] = -1;
    }
    ap_ = block_pattern<F, C>(rows, coarse);
    ap_terms_.clear();
    ap_row_terms_.assign(1, 0);
    for (int i = 0; i < fine; ++i) {
      for (int k = a.row_start[i]; k < a.row_start[i + 1]; ++k) {
        const int j = a.column[k];
        for (int q = p.row_start[j]; q < p.row_start[j + 1]; ++q)
          ap_terms_.push_back({ap_.find(i, p.column[q]), k, q});
      }
      ap_row_terms_.push_back(static_cast<int>(ap_terms_.size()));
    }
    // P^T (A P): coarse row c gathers the rows of A P of the fine nodes that P maps onto c.
    std::vector<std::vector<int>> fine_of(static_cast<std::size_t>(coarse));  // P blocks by column
    for (int i = 0; i < fine; ++i) {
      for (int q = p.row_start[i]; q < p.row_start[i + 1]; ++q) fine_of[p.column[q]].push_back(q);
    }
    std::vector<int> row_of_block(static_cast<std::size_t>(p.block_count()));
    for (int i = 0; i < fine; ++i) {
      for (int q = p.row_start[i]; q < p.row_start[i + 1]; ++q) row_of_block[q] = i;
    }
    std::vector<std::vector<int>> coarse_rows(static_cast<std::size_t>(coarse));
    for (int c = 0; c < coarse; ++c) {
      for (int q : fine_of[c]) {
        const int i = row_of_block[q];
        for (int t = ap_.row_start[i]; t < ap_.row_start[i + 1]; ++t) {
          if (slot[ap_.column[t]] < 0) {
            slot[ap_.column[t]] = 0;
            coarse_rows[c].push_back(ap_.column[t]);
          }
        }
      }
      std::sort(coarse_rows[c].begin(), coarse_rows[c].end());
      for (int d : coarse_rows[c]) slot[d] = -1;
    }
    BlockSparseMatrix<C, C> result = block_pattern<C, C>(coarse_rows, coarse);
    coarse_terms_.clear();
    coarse_row_terms_.assign(1, 0);
    mirror_.clear();
    for (int c = 0; c < coarse; ++c) {
      for (int q : fine_of[c]) {
        const int i = row_of_block[q];
        for (int t = ap_.row_start[i]; t < ap_.row_start[i + 1]; ++t) {
          if (ap_.column[t] >= c) coarse_terms_.push_back({result.find(c, ap_.column[t]), q, t});
        }
      }
      coarse_row_terms_.push_back(static_cast<int>(coarse_terms_.size()));
      for (int t = result.row_start[c]; t < result.row_start[c + 1]; ++t) {
        if (result.column[t] < c) mirror_.push_back({t, result.find(result.column[t], c)});
      }
    }
    return result;
  }

  /// Writes P^T A P into `coarse` (the pattern analyze() returned). `p_scale`, when given,
  /// says that every block of P is a multiple of the identity, P_q = p_scale[q] I (so P^T's
  /// too): each block product is then a scaling, a third of the multiply-adds.
  void compute(const BlockSparseMatrix<F, F>& a, const BlockSparseMatrix<F, C>& p,
               BlockSparseMatrix<C, C>& coarse, const std::vector<double>* p_scale = nullptr) {
    parallel::for_each_weighted(a.block_rows, weight(ap_row_terms_), [&](int i) {
      for (int b = ap_.row_start[i]; b < ap_.row_start[i + 1]; ++b) ap_.values[b].setZero();
      const auto first = ap_terms_.begin() + ap_row_terms_[i];
      const auto last = ap_terms_.begin() + ap_row_terms_[i + 1];
      if (p_scale != nullptr) {
        for (auto t = first; t != last; ++t)
          add_scaled((*p_scale)[static_cast<std::size_t>(t->right)], a.values[t->left],
                     ap_.values[t->out]);
      } else {
        for (auto t = first; t != last; ++t)
          ap_.values[t->out].noalias() += a.values[t->left] * p.values[t->right];
      }
    });
    parallel::for_each_weighted(coarse.block_rows, weight(coarse_row_terms_), [&](int c) {
      for (int b = coarse.row_start[c]; b < coarse.row_start[c + 1]; ++b)
        coarse.values[b].setZero();
      const auto first = coarse_terms_.begin() + coarse_row_terms_[c];
      const auto last = coarse_terms_.begin() + coarse_row_terms_[c + 1];
      if (p_scale != nullptr) {
        for (auto t = first; t != last; ++t)
          add_scaled((*p_scale)[static_cast<std::size_t>(t->left)], ap_.values[t->right],
                     coarse.values[t->out]);
      } else {
        for (auto t = first; t != last; ++t)
          coarse.values[t->out].noalias() += p.values[t->left].transpose() * ap_.values[t->right];
      }
    });
    for (const auto& [to, from] : mirror_) coarse.values[to] = coarse.values[from].transpose();
  }

 private:
  struct Term {
    int out, left, right;
  };
  // out += s block, each entry one fused multiply-add: written out, so that the compiler cannot
  // contract it one way in the serial loop and another in the threads' (the same bits).
  template <class Block>
  static void add_scaled(double s, const Block& block, Block& out) {
    for (Eigen::Index e = 0; e < Block::SizeAtCompileTime; ++e)
      out.data()[e] = std::fma(s, block.data()[e], out.data()[e]);
  }
  // A row's work for parallel::for_each_weighted: its block products (each a few dozen
  // multiply-adds, about one light iteration) on average.
  static int weight(const std::vector<int>& row_terms) {
    const int rows = static_cast<int>(row_terms.size()) - 1;
    return rows > 0 ? std::max(1, row_terms.back() / rows) : 1;
  }

  BlockSparseMatrix<F, C> ap_;
  std::vector<Term> ap_terms_, coarse_terms_;
  std::vector<int> ap_row_terms_, coarse_row_terms_;  // per output row: its first term
  std::vector<std::pair<int, int>> mirror_;
};

}  // namespace animkit
