#include "animkit/cloth/hessian_pattern.h"

#include <Eigen/OrderingMethods>
#include <algorithm>
#include <cassert>

namespace animkit {

namespace {

using Triplet = Eigen::Triplet<double, int>;

void add_block_entries(std::vector<Triplet>& triplets, int row_particle, int col_particle) {
  for (int c = 0; c < 3; ++c) {
    for (int r = 0; r < 3; ++r)
      triplets.emplace_back(3 * row_particle + r, 3 * col_particle + c, 0.0);
  }
}

HessianPattern::BlockOffsets find_block(const SparseMatrix& m, int row_particle, int col_particle) {
  HessianPattern::BlockOffsets offsets;
  for (int c = 0; c < 3; ++c) {
    const int col = 3 * col_particle + c;
    const int* begin = m.innerIndexPtr() + m.outerIndexPtr()[col];
    const int* end = m.innerIndexPtr() + m.outerIndexPtr()[col + 1];
    for (int r = 0; r < 3; ++r) {
      const int* at = std::lower_bound(begin, end, 3 * row_particle + r);
      assert(at != end && *at == 3 * row_particle + r);
      offsets[r + 3 * c] = static_cast<int>(at - m.innerIndexPtr());
    }
  }
  return offsets;
}

}  // namespace

void HessianPattern::assign(const BlockHessian& blocks) {
  double* values = matrix.valuePtr();
  // Every stored entry belongs to exactly one diagonal block or to the (a,b)/(b,a) blocks of
  // the springs joining a and b, so setting the diagonal and then adding couplings covers all.
  std::fill(values, values + matrix.nonZeros(), 0.0);
  for (std::size_t i = 0; i < diagonal.size(); ++i) {
    for (int k = 0; k < 9; ++k) {
      if (diagonal[i][k] >= 0) values[diagonal[i][k]] = blocks.diagonal[i](k % 3, k / 3);
    }
  }
  for (std::size_t s = 0; s < off_diagonal.size(); ++s) {
    for (const BlockOffsets& offsets : off_diagonal[s]) {
      for (int k = 0; k < 9; ++k) {
        if (offsets[k] >= 0) values[offsets[k]] -= blocks.coupling[s](k % 3, k / 3);
      }
    }
  }
}

namespace {

// Re-lays a full pattern out as its upper triangle in AMD order, carrying the offsets along.
void reorder_to_upper_amd(HessianPattern& pattern) {
  const SparseMatrix& full = pattern.matrix;
  const int size = static_cast<int>(full.rows());
  // Eigen's AMD returns the inverse permutation; order[i] is DOF i's new position.
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> inverse;
  Eigen::AMDOrdering<int>()(full, inverse);
  const Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> forward = inverse.inverse();
  pattern.order.assign(forward.indices().data(), forward.indices().data() + size);

  std::vector<int> row_of(full.nonZeros()), col_of(full.nonZeros());
  std::vector<Triplet> upper;
  upper.reserve(static_cast<std::size_t>(full.nonZeros() / 2 + size));
  for (int c = 0; c < size; ++c) {
    for (int k = full.outerIndexPtr()[c]; k < full.outerIndexPtr()[c + 1]; ++k) {
      row_of[k] = pattern.order[full.innerIndexPtr()[k]];
      col_of[k] = pattern.order[c];
      if (row_of[k] <= col_of[k]) upper.emplace_back(row_of[k], col_of[k], 0.0);
    }
  }
  SparseMatrix reordered(size, size);
  reordered.setFromTriplets(upper.begin(), upper.end());
  reordered.makeCompressed();
  const auto relocate = [&](HessianPattern::BlockOffsets& offsets) {
    for (int& k : offsets) {
      if (k < 0) continue;
      if (row_of[k] > col_of[k]) {
        k = -1;  // below the diagonal: the mirror entry carries the value
        continue;
      }
      const int* begin = reordered.innerIndexPtr() + reordered.outerIndexPtr()[col_of[k]];
      const int* end = reordered.innerIndexPtr() + reordered.outerIndexPtr()[col_of[k] + 1];
      k = static_cast<int>(std::lower_bound(begin, end, row_of[k]) - reordered.innerIndexPtr());
    }
  };
  for (auto& block : pattern.diagonal) relocate(block);
  for (auto& pair : pattern.off_diagonal) {
    relocate(pair[0]);
    relocate(pair[1]);
  }
  pattern.matrix = std::move(reordered);
}

}  // namespace

HessianPattern build_hessian_pattern(const ClothModel& model, PatternLayout layout) {
  const int n = model.particle_count();
  std::vector<Triplet> triplets;
  triplets.reserve(9 * (static_cast<std::size_t>(n) + 2 * model.springs.size()));
  for (int i = 0; i < n; ++i) add_block_entries(triplets, i, i);
  for (const auto& [a, b] : model.springs) {
    if (model.pinned[a] || model.pinned[b]) continue;
    add_block_entries(triplets, a, b);
    add_block_entries(triplets, b, a);
  }
  HessianPattern pattern;
  pattern.matrix.resize(3 * n, 3 * n);
  // Duplicates (two springs joining the same pair) merge into one entry.
  pattern.matrix.setFromTriplets(triplets.begin(), triplets.end());
  pattern.matrix.makeCompressed();

  pattern.diagonal.reserve(n);
  for (int i = 0; i < n; ++i) pattern.diagonal.push_back(find_block(pattern.matrix, i, i));
  HessianPattern::BlockOffsets none;
  none.fill(-1);
  pattern.off_diagonal.reserve(model.springs.size());
  for (const auto& [a, b] : model.springs) {
    if (model.pinned[a] || model.pinned[b]) {
      pattern.off_diagonal.push_back({none, none});
    } else {
      pattern.off_diagonal.push_back(
          {find_block(pattern.matrix, a, b), find_block(pattern.matrix, b, a)});
    }
  }
  if (layout == PatternLayout::upper_amd) reorder_to_upper_amd(pattern);
  return pattern;
}

}  // namespace animkit
