#include <cmath>
#include <string>

#include "../stacked_vectors.h"
#include "animkit/cloth/friction.h"
#include "animkit/core/validation.h"
#include "contact_candidates.h"
#include "friction_pair.h"

namespace animkit {

namespace {

std::optional<Error> check_coefficient(const std::string& what, double mu) {
  if (!kFrictionRange.contains(mu)) return Error{kFrictionRange.refusal("friction " + what, mu)};
  return std::nullopt;
}

// f0(b) - f0(a) without the cancellation of two nearly equal values where it matters: with
// b^2 - a^2 = q computed from the motion (q = du . (2 u + du)), b - a = q / (a + b), and
//   beyond eps:  f0(b) - f0(a) = b - a
//   below eps:   f0(b) - f0(a) = (b - a) ((a + b) / eps - (a^2 + a b + b^2) / (3 eps^2))
// (a cubic's difference factored); across eps, the plain difference.
double f0_difference(double a, double b, double q, double eps) {
  if (a >= eps && b >= eps) return q / (a + b);
  if (a < eps && b < eps) {
    if (!(a + b > 0.0)) return 0.0;
    return q / (a + b) * ((a + b) / eps - (a * a + a * b + b * b) / (3.0 * eps * eps));
  }
  return friction_f0(b, eps) - friction_f0(a, eps);
}

}  // namespace

std::optional<Error> FrictionSettings::validate() const {
  for (std::size_t m = 0; m < obstacles.size(); ++m) {
    if (auto error = check_coefficient("on obstacle " + std::to_string(m), obstacles[m]))
      return error;
  }
  if (auto error = check_coefficient("on the ground", ground)) return error;
  if (auto error = check_coefficient("in self-contact", self)) return error;
  if (!std::isfinite(smoothing_velocity) || smoothing_velocity <= 0.0) {
    return Error{"friction smoothing velocity must be > 0 m/s, got " +
                 format_number(smoothing_velocity)};
  }
  if (max_passes < 1)
    return Error{"friction passes must be at least 1, got " + std::to_string(max_passes)};
  return std::nullopt;
}

struct FrictionTerm::Impl {
  std::shared_ptr<const ContactTerm> contact;
  FrictionSettings settings;
  LogBarrier barrier = *LogBarrier::create(1.0);  // the contact's, on squared distances
  int n = 0;                                      // cloth particles
  double eps_u = 0.0;                             // eps_v h, m
  int passes = 0;
  Eigen::VectorXd x_start;          // x_n
  ContactPairFinder finder;         // the contact pairs at the lag
  std::vector<ContactPair> nearby;  // kept for their capacity
  std::vector<FrictionPair> pairs;

  const ContactGeometry& geometry() const { return contact->geometry(); }

  double mu_of(const ContactPair& pair) const {
    if (pair.kind == ContactKind::ground) return settings.ground;
    for (int v : pair.vertices) {
      if (v >= n) return settings.obstacles[geometry().obstacle_mesh_of(v - n)];
    }
    return settings.self;
  }

  // Freezes lambda, w and T for every pair active at cloth positions x, the obstacles at
  // `obstacles` (3 per vertex). Returns false if the broad phase could not run (a non-finite x).
  bool lag(const Eigen::VectorXd& x, const Eigen::VectorXd& obstacles) {
    pairs.clear();
    const ContactGeometry& g = geometry();
    const double ground = contact->ground_height().value_or(0.0);
    if (!finder.gather(g, x, nullptr, contact->settings().thickness, contact->ground_height(),
                       nearby)) {
      return false;
    }
    const double kappa = contact->stiffness();
    for (const ContactPair& pair : nearby) {
      std::array<Vec3, 4> p;
      for (int i = 0; i < pair.vertex_count(); ++i) {
        const int v = pair.vertices[i];
        p[i] = v < n ? at(x, v) : at(obstacles, v - n);
      }
      auto lagged = lag_friction_pair(pair, p, ground, kappa, barrier, mu_of(pair));
      if (!lagged) continue;
      // The obstacle's own motion over the substep (zero for fixed meshes).
      for (int i = 0; i < lagged->count; ++i) {
        const int v = lagged->vertices[i];
        if (v < n) continue;
        lagged->obstacle_motion += lagged->weights[i] * at(g.obstacle_motion, v - n);
      }
      if (pair.thickness > 0.0) {
        // A sphere's centre: its surface point facing the triangle also turns with its spin.
        Vec3 separation = Vec3::Zero();  // from the triangle's closest point to the centre
        for (int i = 0; i < 4; ++i) separation += lagged->weights[i] * p[i];
        const auto mesh = static_cast<std::size_t>(g.obstacle_mesh_of(pair.vertices[0] - n));
        lagged->obstacle_motion +=
            g.obstacle_spin[mesh] * (-pair.thickness * separation.normalized());
      }
      pairs.push_back(*lagged);
    }
    return true;
  }
};

FrictionTerm::FrictionTerm(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
FrictionTerm::~FrictionTerm() = default;

Result<std::shared_ptr<FrictionTerm>> FrictionTerm::create(
    std::shared_ptr<const ContactTerm> contact, const FrictionSettings& settings) {
  if (!contact) return fail("friction needs a contact term");
  if (auto error = settings.validate()) return fail(error->message);
  const int meshes = static_cast<int>(contact->geometry().obstacle_mesh_start.size());
  if (static_cast<int>(settings.obstacles.size()) != meshes) {
    return fail("friction lists " + std::to_string(settings.obstacles.size()) +
                " obstacle coefficients for " + std::to_string(meshes) + " obstacle meshes");
  }
  auto impl = std::make_unique<Impl>();
  const double dhat = contact->settings().thickness;
  impl->barrier = *LogBarrier::create(dhat * dhat);
  impl->n = contact->geometry().cloth_vertices();
  impl->contact = std::move(contact);
  impl->settings = settings;
  return std::shared_ptr<FrictionTerm>(new FrictionTerm(std::move(impl)));
}

void FrictionTerm::prepare(const ClothState& state, double h) {
  impl_->x_start = state.positions;
  impl_->eps_u = impl_->settings.smoothing_velocity * h;
  impl_->passes = 1;
  if (!impl_->lag(state.positions, impl_->geometry().obstacle_start_positions))
    impl_->pairs.clear();
}

bool FrictionTerm::relag(const Eigen::VectorXd& x) {
  // IPC re-lags at the converged x (obstacles where they are now); the displacement still
  // counts from x_n. Nothing to refresh when no pair had friction and none has now.
  if (impl_->passes >= impl_->settings.max_passes) return false;
  ++impl_->passes;
  const bool had_pairs = !impl_->pairs.empty();
  if (!impl_->lag(x, impl_->geometry().obstacle_positions)) impl_->pairs.clear();
  return had_pairs || !impl_->pairs.empty();
}

double FrictionTerm::value(const Eigen::VectorXd& x) const {
  double sum = 0.0;
  for (const FrictionPair& pair : impl_->pairs) {
    const Eigen::Vector2d u = friction_tangent_motion(pair, x, impl_->x_start, impl_->n);
    sum += pair.mu_lambda * friction_f0(u.norm(), impl_->eps_u);
  }
  return sum;
}

double FrictionTerm::difference(const Eigen::VectorXd& x, const Eigen::VectorXd& step) const {
  // Pair by pair, each in a cancellation-free form (f0_difference): the line search resolves
  // decreases far below the rounding of D itself.
  double sum = 0.0;
  for (const FrictionPair& pair : impl_->pairs) {
    const Eigen::Vector2d u = friction_tangent_motion(pair, x, impl_->x_start, impl_->n);
    Vec3 dr = Vec3::Zero();
    for (int i = 0; i < pair.count; ++i) {
      const int v = pair.vertices[i];
      if (v < impl_->n) dr += pair.weights[i] * step.segment<3>(3 * v);
    }
    const Eigen::Vector2d du = pair.basis.transpose() * dr;
    const double q = du.dot(2.0 * u + du);
    sum += pair.mu_lambda * f0_difference(u.norm(), (u + du).norm(), q, impl_->eps_u);
  }
  return sum;
}

void FrictionTerm::add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  // grad_{x_i} mu lambda f0(|u|) = mu lambda (f1(|u|) / |u|) w_i T u.
  for (const FrictionPair& pair : impl_->pairs) {
    const Eigen::Vector2d u = friction_tangent_motion(pair, x, impl_->x_start, impl_->n);
    const Vec3 force =
        pair.mu_lambda * friction_f1_over_y(u.norm(), impl_->eps_u) * (pair.basis * u);
    for (int i = 0; i < pair.count; ++i) {
      const int v = pair.vertices[i];
      if (v < impl_->n) gradient.segment<3>(3 * v) += pair.weights[i] * force;
    }
  }
}

void FrictionTerm::add_hessian(const Eigen::VectorXd& x, bool /*projected: PSD as it is*/,
                               std::vector<HessianBlock>& blocks) const {
  // Block (i, j) = mu lambda w_i w_j T H_u T^T, H_u the Hessian of f0(|u|) in u.
  for (const FrictionPair& pair : impl_->pairs) {
    const Eigen::Vector2d u = friction_tangent_motion(pair, x, impl_->x_start, impl_->n);
    const Eigen::Matrix3d tangent = pair.mu_lambda * pair.basis *
                                    friction_tangent_hessian(u, impl_->eps_u) *
                                    pair.basis.transpose();
    for (int i = 0; i < pair.count; ++i) {
      if (pair.vertices[i] >= impl_->n) continue;
      for (int j = i; j < pair.count; ++j) {
        if (pair.vertices[j] >= impl_->n) continue;
        blocks.push_back(
            {pair.vertices[i], pair.vertices[j], pair.weights[i] * pair.weights[j] * tangent});
      }
    }
  }
}

FrictionStats FrictionTerm::stats() const {
  FrictionStats s;
  for (const FrictionPair& pair : impl_->pairs) {
    switch (pair.kind) {
      case ContactKind::point_triangle:
        ++s.point_triangle_pairs;
        break;
      case ContactKind::edge_edge:
        ++s.edge_edge_pairs;
        break;
      case ContactKind::ground:
        ++s.ground_pairs;
        break;
    }
    s.normal_force_sum += pair.normal_force;
  }
  s.passes = impl_->passes;
  return s;
}

}  // namespace animkit
