#include "coupling_blocks.h"

#include <cassert>

namespace animkit {

void CouplingBlocks::clear(int nodes) {
  nodes_ = nodes;
  added_.clear();
  upper_.clear();
}

void CouplingBlocks::add(int row, int col, const Eigen::Matrix3d& value) {
  assert(row != col && row >= 0 && col >= 0 && row < nodes_ && col < nodes_);
  if (row < col) {
    added_.push_back({row, col, value});
  } else {
    added_.push_back({col, row, value.transpose()});
  }
}

void CouplingBlocks::stable_sort_by(const std::vector<int>& in, std::vector<int>& out,
                                    int Entry::*key) {
  bucket_.assign(static_cast<std::size_t>(nodes_) + 1, 0);
  for (const int k : in) ++bucket_[added_[k].*key + 1];
  for (int r = 0; r < nodes_; ++r) bucket_[r + 1] += bucket_[r];
  out.resize(in.size());
  for (const int k : in) out[bucket_[added_[k].*key]++] = k;
}

void CouplingBlocks::assemble() {
  // Sort by (row, col), ties in the order added: the duplicates' sum has one order. Two
  // stable counting sorts, by column and then by row (a radix sort), linear in the blocks
  // and the nodes: a comparison sort here took 8% of a contact step (drape-sphere 41 x 41).
  by_column_.resize(added_.size());
  for (std::size_t k = 0; k < by_column_.size(); ++k) by_column_[k] = static_cast<int>(k);
  stable_sort_by(by_column_, order_, &Entry::col);
  by_column_.swap(order_);
  stable_sort_by(by_column_, order_, &Entry::row);
  upper_.clear();
  for (int k : order_) {
    const Entry& e = added_[k];
    if (!upper_.empty() && upper_.back().row == e.row && upper_.back().col == e.col) {
      upper_.back().value += e.value;
    } else {
      upper_.push_back(e);
    }
  }
  // Both triangles in compressed block rows. Row r holds its lower blocks (r', r), r' < r,
  // met in ascending r' in upper_, then its upper blocks (r, c), c > r, ascending: sorted.
  full_.block_rows = full_.block_cols = nodes_;
  full_.row_start.assign(static_cast<std::size_t>(nodes_) + 1, 0);
  for (const Entry& e : upper_) {
    ++full_.row_start[e.row + 1];
    ++full_.row_start[e.col + 1];
  }
  for (int r = 0; r < nodes_; ++r) full_.row_start[r + 1] += full_.row_start[r];
  const std::size_t blocks = 2 * upper_.size();
  full_.column.resize(blocks);
  full_.values.resize(blocks);
  row_fill_.assign(full_.row_start.begin(), full_.row_start.end() - 1);
  for (const Entry& e : upper_) {  // lower blocks first, rows by ascending column
    const int at = row_fill_[e.col]++;
    full_.column[at] = e.row;
    full_.values[at] = e.value.transpose();
  }
  for (const Entry& e : upper_) {
    const int at = row_fill_[e.row]++;
    full_.column[at] = e.col;
    full_.values[at] = e.value;
  }
}

void CouplingBlocks::restrict_to(const Matrix& p, CouplingBlocks& coarse,
                                 std::vector<DiagonalPart>& within) const {
  // (P^T E P)_cd = sum over blocks B_ij of E of P_ic^T B_ij P_jd; E holds B_ij and B_ij^T at
  // (j, i), so each upper block gives X = P_ic^T B P_jd at (c, d) and X^T at (d, c).
  coarse.clear(p.block_cols);
  within.clear();
  for (const Entry& e : upper_) {
    for (int q = p.row_start[e.row]; q < p.row_start[e.row + 1]; ++q) {
      const int c = p.column[q];
      const Eigen::Matrix3d left = p.values[q].transpose() * e.value;
      for (int t = p.row_start[e.col]; t < p.row_start[e.col + 1]; ++t) {
        const int d = p.column[t];
        const Eigen::Matrix3d x = left * p.values[t];
        if (c == d) {
          within.push_back({c, x + x.transpose()});
        } else {
          coarse.add(c, d, x);
        }
      }
    }
  }
  coarse.assemble();
}

void CouplingBlocks::add_within(const std::vector<DiagonalPart>& within, Matrix& a,
                                const std::vector<int>& diagonal) {
  for (const DiagonalPart& part : within) a.values[diagonal[part.node]] += part.value;
}

}  // namespace animkit
