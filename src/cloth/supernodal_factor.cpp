#include "animkit/cloth/supernodal_factor.h"

#include <array>
#include <cassert>

namespace animkit {

namespace {

using Triple = std::array<double, 3>;

// sum_c l[c] (y[3c], y[3c + 1], y[3c + 2]), over four interleaved partial sums per coordinate:
// one chain of dependent additions would make the loop wait on the adder's latency.
Triple dot3(const double* l, const double* y, int n) {
  double a[4][3] = {};
  int c = 0;
  for (; c + 4 <= n; c += 4) {
    for (int u = 0; u < 4; ++u) {
      for (int j = 0; j < 3; ++j) a[u][j] += l[c + u] * y[3 * (c + u) + j];
    }
  }
  for (; c < n; ++c) {
    for (int j = 0; j < 3; ++j) a[0][j] += l[c] * y[3 * c + j];
  }
  return {(a[0][0] + a[1][0]) + (a[2][0] + a[3][0]), (a[0][1] + a[1][1]) + (a[2][1] + a[3][1]),
          (a[0][2] + a[1][2]) + (a[2][2] + a[3][2])};
}

}  // namespace

void SupernodalFactor::find_supernodes(
    const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower) {
  const int n = static_cast<int>(lower.cols());
  const int* outer = lower.outerIndexPtr();
  const int* inner = lower.innerIndexPtr();
  const auto count = [outer](int j) { return outer[j + 1] - outer[j]; };
  int values = 0;
  for (int j = 0; j < n;) {
    // Column j + w joins when column j + w - 1's pattern is {j + w - 1, j + w} + column
    // j + w's (same count less one, and j + w directly below the diagonal): the patterns of
    // L's columns nest along the elimination tree, so equal counts mean equal patterns.
    int w = 1;
    while (j + w < n && count(j + w - 1) == count(j + w) + 1 &&
           inner[outer[j + w - 1] + 1] == j + w)
      ++w;
    Supernode s;
    s.first_column = j;
    s.width = w;
    s.rows_begin = static_cast<int>(rows_.size());
    s.row_count = count(j + w - 1) - 1;
    s.values_begin = values;
    for (int k = outer[j + w - 1] + 1; k < outer[j + w]; ++k) rows_.push_back(inner[k]);
    values += w * w + s.row_count * w;
    supernodes_.push_back(s);
    j += w;
  }
  values_.assign(static_cast<std::size_t>(values), 0.0);
}

void SupernodalFactor::assign(const Eigen::SparseMatrix<double, Eigen::ColMajor, int>& lower) {
  if (supernodes_.empty()) find_supernodes(lower);
  const int* outer = lower.outerIndexPtr();
  const double* value = lower.valuePtr();
  for (const Supernode& s : supernodes_) {
    const int w = s.width;
    double* triangle = values_.data() + s.values_begin;
    double* rectangle = triangle + w * w;
    for (int c = 0; c < w; ++c) {
      const double* column = value + outer[s.first_column + c];  // rows c, c + 1, ..., then R
      for (int r = c; r < w; ++r) triangle[r + w * c] = column[r - c];
      for (int k = 0; k < s.row_count; ++k) rectangle[k * w + c] = column[w - c + k];
    }
  }
}

void SupernodalFactor::solve(double* x) const {
  // L y = b, supernodes in order: the triangle, then y_i -= L_i,block y_block for its rows.
  for (const Supernode& s : supernodes_) {
    const int w = s.width;
    const double* triangle = values_.data() + s.values_begin;
    const double* rectangle = triangle + w * w;
    double* block = x + 3 * s.first_column;
    for (int c = 0; c < w; ++c) {
      const double d = 1.0 / triangle[c + w * c];
      const double b0 = block[3 * c] * d, b1 = block[3 * c + 1] * d, b2 = block[3 * c + 2] * d;
      block[3 * c] = b0;
      block[3 * c + 1] = b1;
      block[3 * c + 2] = b2;
      for (int r = c + 1; r < w; ++r) {
        const double l = triangle[r + w * c];
        block[3 * r] -= l * b0;
        block[3 * r + 1] -= l * b1;
        block[3 * r + 2] -= l * b2;
      }
    }
    const int* rows = rows_.data() + s.rows_begin;
    for (int k = 0; k < s.row_count; ++k) {
      double* xi = x + 3 * rows[k];
      const Triple dot = dot3(rectangle + k * w, block, w);
      xi[0] -= dot[0];
      xi[1] -= dot[1];
      xi[2] -= dot[2];
    }
  }
  // L^T x = y, supernodes in reverse: x_block -= L_rows,block^T x_rows, then the triangle.
  for (auto it = supernodes_.rbegin(); it != supernodes_.rend(); ++it) {
    const Supernode& s = *it;
    const int w = s.width;
    const double* triangle = values_.data() + s.values_begin;
    const double* rectangle = triangle + w * w;
    double* block = x + 3 * s.first_column;
    const int* rows = rows_.data() + s.rows_begin;
    for (int k = 0; k < s.row_count; ++k) {
      const double* l = rectangle + k * w;
      const double* xi = x + 3 * rows[k];
      const double x0 = xi[0], x1 = xi[1], x2 = xi[2];
      for (int c = 0; c < w; ++c) {
        block[3 * c] -= l[c] * x0;
        block[3 * c + 1] -= l[c] * x1;
        block[3 * c + 2] -= l[c] * x2;
      }
    }
    for (int c = w - 1; c >= 0; --c) {
      const Triple dot = dot3(triangle + c + 1 + w * c, block + 3 * (c + 1), w - c - 1);
      const double d = 1.0 / triangle[c + w * c];
      block[3 * c] = (block[3 * c] - dot[0]) * d;
      block[3 * c + 1] = (block[3 * c + 1] - dot[1]) * d;
      block[3 * c + 2] = (block[3 * c + 2] - dot[2]) * d;
    }
  }
}

}  // namespace animkit
