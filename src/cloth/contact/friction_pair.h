#pragma once
// One contact pair's lagged friction (IPC, Li et al. 2020, section 5; friction.h has the model):
// what is frozen at the lag (normal force lambda, closest-point weights w, tangent basis T) and
// the pair's dissipative potential mu lambda f0(|u|), u = T^T r, r = sum_i w_i d_i the relative
// displacement of the closest points (d_i each vertex's displacement over the substep), with
// its gradient and Hessian in the pair's cloth vertices.
#include <Eigen/Core>
#include <array>
#include <optional>

#include "animkit/collision/barrier.h"
#include "animkit/core/types.h"
#include "contact_pair.h"

namespace animkit {

/// IPC's friction smoothing f0 (Li et al. 2020, eq. 16) and its derivatives, with eps = eps_v h
/// (m): f0(y) = -y^3 / (3 eps^2) + y^2 / eps + eps / 3 below eps, y beyond; f1 = f0'.
/// f0 is C^2 at eps (f1(eps) = 1, f1'(eps) = 0), convex and increasing on [0, inf).
double friction_f0(double y, double eps);
double friction_f1(double y, double eps);

/// The closest points of a contact pair as weights on its vertices: sum_i w_i p_i is the
/// vector from the closest point of the second primitive to that of the first (point minus
/// triangle point; edge a's point minus edge b's; the particle minus the ground below it).
///   point-triangle  w = (1, -b_a, -b_b, -b_c), b the closest point's barycentric coordinates
///   edge-edge       w = (1 - s, s, -(1 - t), -t), s and t the closest points' parameters
///   ground          w = (1): the particle's displacement itself
/// Closest points by Ericson, Real-Time Collision Detection (2005), sections 5.1.5 and 5.1.9.
std::array<double, 4> closest_point_weights(const ContactPair& pair, const std::array<Vec3, 4>& p);

struct FrictionPair {
  ContactKind kind = ContactKind::point_triangle;
  std::array<int, 4> vertices{-1, -1, -1, -1};  ///< contact index space (cloth first)
  int count = 0;                                ///< vertices in use: 1 (ground) or 4
  std::array<double, 4> weights{};              ///< w, see closest_point_weights
  Eigen::Matrix<double, 3, 2> basis = Eigen::Matrix<double, 3, 2>::Zero();  ///< T, orthonormal
  double normal_force = 0.0;                                                ///< lambda (N)
  double mu_lambda = 0.0;                                                   ///< mu times lambda (N)
  /// sum of w_i d_i over the pair's obstacle vertices (their own motion over the substep, m).
  Vec3 obstacle_motion = Vec3::Zero();
};

/// Lags one contact pair at positions p (p[i] of vertices[i]): lambda = kappa |b'(d)| 2 sqrt(d),
/// the barrier's force on the pair for the squared distance d (IPC section 5: the contact
/// term's barrier acts on d, so its force along the distance sqrt(d) is kappa b'(d) d(d)/d
/// sqrt(d)), the weights and a basis of the plane normal to the closest points' separation.
/// Edge-edge forces leave out the parallel-edge mollifier, as IPC's toolkit does (it only fades
/// the barrier where the normal is ill-defined). None when the pair is at or beyond dhat, at
/// zero distance, or mu is 0. `obstacle_motion` is filled by the caller.
std::optional<FrictionPair> lag_friction_pair(const ContactPair& pair, const std::array<Vec3, 4>& p,
                                              double ground, double kappa,
                                              const LogBarrier& barrier, double mu);

/// The tangential relative displacement u = T^T r for r = obstacle_motion + sum over the
/// pair's cloth vertices (index < cloth_vertices) of w_i (x_i - x_start_i).
Eigen::Vector2d friction_tangent_motion(const FrictionPair& pair, const Eigen::VectorXd& x,
                                        const Eigen::VectorXd& x_start, int cloth_vertices);

/// The 2x2 Hessian of f0(|u|) in u: a I + c u u^T, PSD (see friction_pair.cpp).
Eigen::Matrix2d friction_tangent_hessian(const Eigen::Vector2d& u, double eps);

/// f1(|u|) / |u| (its limit 2 / eps at u = 0): grad_u f0(|u|) = (f1 / |u|) u.
double friction_f1_over_y(double y, double eps);

}  // namespace animkit
