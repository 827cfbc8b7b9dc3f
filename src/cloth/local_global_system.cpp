#include "animkit/cloth/local_global_system.h"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCholesky>
#include <cassert>
#include <utility>

#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/supernodal_factor.h"

namespace animkit {

namespace {

using Sparse = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
using Triplet = Eigen::Triplet<double, int>;
using Permutation = Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int>;

// The entries of P, each tagged with the matrix (S, C or M) it belongs to.
struct Entries {
  std::vector<Triplet> stiffness, damping, mass;
};

Entries collect_entries(const ClothModel& model) {
  Entries e;
  const auto free = [&model](int i) { return !model.pinned[i]; };
  // k (e_a - e_b)(e_a - e_b)^T restricted to the free particles.
  const auto add_pair = [&free](std::vector<Triplet>& out, int a, int b, double weight) {
    if (free(a)) out.emplace_back(a, a, weight);
    if (free(b)) out.emplace_back(b, b, weight);
    if (free(a) && free(b)) {
      out.emplace_back(a, b, -weight);
      out.emplace_back(b, a, -weight);
    }
  };
  for (int i = 0; i < model.particle_count(); ++i) {
    if (free(i)) {
      e.mass.emplace_back(i, i, model.mass[i]);
    } else {
      e.stiffness.emplace_back(i, i, 1.0);  // eliminated: the identity's row
    }
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const auto [a, b] = model.springs[s];
    add_pair(e.stiffness, a, b, model.stiffness[s]);
    // Only springs with stiffness carry a dashpot (see IncrementalPotential::prepare).
    if (model.stiffness[s] > 0.0) add_pair(e.damping, a, b, 1.0);
  }
  // A bend's constant Hessian c w w^T (bend_energy.h), entered exactly.
  for (int k = 0; k < model.bend_count(); ++k) {
    const auto& p = model.bends[k];
    const auto& w = model.bend_weights[k];
    const int size = bend_size(p);
    for (int i = 0; i < size; ++i) {
      for (int j = 0; j < size; ++j) {
        if (free(p[i]) && free(p[j]))
          e.stiffness.emplace_back(p[i], p[j], model.bend_stiffness[k] * w[i] * w[j]);
      }
    }
  }
  return e;
}

// The lower triangle of the permuted matrix holding `values`, on the pattern of `all` (every
// entry of S, C and M, as zeros), so the three matrices share one pattern entry for entry.
Sparse permuted_lower(const std::vector<Triplet>& values, const std::vector<Triplet>& all,
                      const std::vector<int>& order) {
  std::vector<Triplet> lower;
  lower.reserve(values.size() + all.size());
  const auto add = [&](const Triplet& t, double value) {
    const int r = order[t.row()], c = order[t.col()];
    if (r >= c) lower.emplace_back(r, c, value);
  };
  for (const Triplet& t : all) add(t, 0.0);
  for (const Triplet& t : values) add(t, t.value());
  const int n = static_cast<int>(order.size());
  Sparse m(n, n);
  m.setFromTriplets(lower.begin(), lower.end());
  m.makeCompressed();
  return m;
}

}  // namespace

// The factor is computed on the already permuted matrix (natural ordering), and copied into
// supernodes for the solves, which carry the three coordinates together.
struct LocalGlobalSystem::Factor {
  Eigen::SimplicialLLT<Sparse, Eigen::Lower, Eigen::NaturalOrdering<int>> llt;
  SupernodalFactor supernodal;
};

LocalGlobalSystem::LocalGlobalSystem(const ClothModel& model)
    : model_(model), factor_(std::make_unique<Factor>()) {
  const int n = model.particle_count();
  const Entries entries = collect_entries(model);
  std::vector<Triplet> all = entries.stiffness;
  all.insert(all.end(), entries.damping.begin(), entries.damping.end());
  all.insert(all.end(), entries.mass.begin(), entries.mass.end());
  for (Triplet& t : all) t = Triplet(t.row(), t.col(), 1.0);  // pattern only

  Sparse pattern(n, n);
  pattern.setFromTriplets(all.begin(), all.end());
  Permutation inverse;  // Eigen's AMD returns the inverse permutation
  Eigen::AMDOrdering<int>()(pattern, inverse);
  const Permutation forward = inverse.inverse();
  order_.assign(forward.indices().data(), forward.indices().data() + n);

  stiffness_ = permuted_lower(entries.stiffness, all, order_);
  damping_ = permuted_lower(entries.damping, all, order_);
  mass_ = permuted_lower(entries.mass, all, order_);
  assert(stiffness_.nonZeros() == mass_.nonZeros() && damping_.nonZeros() == mass_.nonZeros());
  matrix_ = mass_;
  factor_->llt.analyzePattern(matrix_);
  permuted_.resize(3 * n);
}

LocalGlobalSystem::~LocalGlobalSystem() = default;

bool LocalGlobalSystem::factorize(double h) {
  if (h == h_) return false;
  h_ = h;
  const Eigen::Index nnz = matrix_.nonZeros();
  Eigen::Map<Eigen::VectorXd>(matrix_.valuePtr(), nnz) =
      Eigen::Map<const Eigen::VectorXd>(stiffness_.valuePtr(), nnz) +
      (model_.damping / h) * Eigen::Map<const Eigen::VectorXd>(damping_.valuePtr(), nnz) +
      (1.0 / (h * h)) * Eigen::Map<const Eigen::VectorXd>(mass_.valuePtr(), nnz);
  factor_->llt.factorize(matrix_);
  // P is symmetric positive definite by construction (M / h^2 > 0 on every free particle).
  assert(factor_->llt.info() == Eigen::Success);
  factor_->supernodal.assign(factor_->llt.matrixL().nestedExpression());
  return true;
}

void LocalGlobalSystem::solve_in_place(Eigen::VectorXd& rhs) {
  const int n = static_cast<int>(order_.size());
  for (int i = 0; i < n; ++i) permuted_.segment<3>(3 * order_[i]) = rhs.segment<3>(3 * i);
  factor_->supernodal.solve(permuted_.data());
  for (int i = 0; i < n; ++i) rhs.segment<3>(3 * i) = permuted_.segment<3>(3 * order_[i]);
}

long LocalGlobalSystem::factor_non_zeros() const {
  return factor_->llt.matrixL().nestedExpression().nonZeros();
}

}  // namespace animkit
