#include "animkit/cloth/hessian_pattern.h"

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
    for (int k = 0; k < 9; ++k) values[diagonal[i][k]] = blocks.diagonal[i](k % 3, k / 3);
  }
  for (std::size_t s = 0; s < off_diagonal.size(); ++s) {
    if (off_diagonal[s][0][0] < 0) continue;  // touches a pinned particle: no off-diagonal
    for (const BlockOffsets& offsets : off_diagonal[s]) {
      for (int k = 0; k < 9; ++k) values[offsets[k]] -= blocks.coupling[s](k % 3, k / 3);
    }
  }
}

HessianPattern build_hessian_pattern(const ClothModel& model) {
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
  return pattern;
}

}  // namespace animkit
