#include "animkit/cloth/aerodynamics.h"

#include <cmath>
#include <numbers>
#include <string>

#include "animkit/core/validation.h"
#include "stacked_vectors.h"

namespace animkit {

namespace {

// The gust factor in [0, 1]: two sinusoids of incommensurate frequencies (ratio 2.17), so the
// gusts never repeat exactly, with amplitudes summing to 1.
double gust_factor(double frequency, double tau) {
  const double w = 2.0 * std::numbers::pi * frequency;
  return 0.5 + 0.5 * (0.6 * std::sin(w * tau) + 0.4 * std::sin(2.17 * w * tau + 1.3));
}

std::optional<Error> non_negative(const char* name, double value) {
  if (!std::isfinite(value) || value < 0.0)
    return Error{std::string("air ") + name + " must be finite and >= 0, got " +
                 format_number(value)};
  return std::nullopt;
}

}  // namespace

Vec3 WindSettings::at(const Vec3& x, double t) const {
  const double speed = velocity.norm();
  // Gusts travel with the steady wind: a point downwind meets each one later.
  const double tau = speed > 0.0 ? t - x.dot(velocity) / (speed * speed) : t;
  return velocity + gust * gust_factor(gust_frequency, tau);
}

std::optional<Error> AirSettings::validate() const {
  if (!is_finite(wind.velocity)) return Error{"wind velocity has a non-finite coordinate"};
  if (!is_finite(wind.gust)) return Error{"wind gust has a non-finite coordinate"};
  if (!kSpeedRange.contains(wind.velocity))
    return Error{kSpeedRange.refusal("wind velocity (m/s)", wind.velocity)};
  if (!kSpeedRange.contains(wind.gust))
    return Error{kSpeedRange.refusal("wind gust (m/s)", wind.gust)};
  if (!std::isfinite(wind.gust_frequency) || wind.gust_frequency <= 0.0)
    return Error{"wind gust frequency must be > 0 Hz, got " + format_number(wind.gust_frequency)};
  if (auto e = non_negative("density", density)) return e;
  if (auto e = non_negative("normal drag coefficient", normal_drag)) return e;
  if (auto e = non_negative("tangential drag coefficient", tangential_drag)) return e;
  return std::nullopt;
}

Result<std::shared_ptr<AirTerm>> AirTerm::create(const ClothModel& model,
                                                 const AirSettings& settings) {
  if (auto error = settings.validate()) return fail(error->message);
  if (model.triangles.empty()) return fail("air needs the cloth's triangles, and it has none");
  return std::shared_ptr<AirTerm>(new AirTerm(model, settings));
}

AirTerm::AirTerm(const ClothModel& model, const AirSettings& settings)
    : triangles_(model.triangles),
      settings_(settings),
      normal_(model.triangles.size()),
      wind_(model.triangles.size()),
      area_(model.triangles.size()) {}

void AirTerm::prepare(const ClothState& state, double h) {
  h_ = h;
  x_start_ = state.positions;
  // Implicit Euler: forces at the substep's end, on the simulation's clock (an undone step or
  // a restored state takes the wind back with it).
  const double t_end = state.time + h;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    const auto [a, b, c] = triangles_[t];
    const Vec3 pa = at(x_start_, a), pb = at(x_start_, b), pc = at(x_start_, c);
    const Vec3 cross = (pb - pa).cross(pc - pa);
    const double twice_area = cross.norm();
    area_[t] = 0.5 * twice_area;
    normal_[t] = twice_area > 0.0 ? Vec3(cross / twice_area) : Vec3::Zero();
    wind_[t] = settings_.wind.at((pa + pb + pc) / 3.0, t_end);
  }
  time_ = t_end;
}

void AirTerm::relative_velocity(const Eigen::VectorXd& x, int t, double& normal,
                                Vec3& tangential) const {
  Vec3 moved = Vec3::Zero();
  for (int i : triangles_[t]) moved += at(x, i) - at(x_start_, i);
  const Vec3 r = moved / (3.0 * h_) - wind_[t];
  normal = r.dot(normal_[t]);
  tangential = r - normal * normal_[t];
}

double AirTerm::value(const Eigen::VectorXd& x) const {
  double energy = 0.0;
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    double s = 0.0;
    Vec3 u;
    relative_velocity(x, static_cast<int>(t), s, u);
    const double ut = u.norm();
    energy += area_[t] * (settings_.normal_drag * std::abs(s) * s * s +
                          settings_.tangential_drag * ut * ut * ut);
  }
  return h_ * settings_.density / 6.0 * energy;
}

void AirTerm::add_gradient(const Eigen::VectorXd& x, Eigen::VectorXd& gradient) const {
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    double s = 0.0;
    Vec3 u;
    relative_velocity(x, static_cast<int>(t), s, u);
    // dD/dx_i = rho A / 6 [C_n |s| s n + C_t |r_t| r_t], the same for the three corners.
    const Vec3 g = settings_.density * area_[t] / 6.0 *
                   (settings_.normal_drag * std::abs(s) * s * normal_[t] +
                    settings_.tangential_drag * u.norm() * u);
    for (int i : triangles_[t]) gradient.segment<3>(3 * i) += g;
  }
}

void AirTerm::add_hessian(const Eigen::VectorXd& x, bool /*projected: always PSD*/,
                          std::vector<HessianBlock>& blocks) const {
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    if (area_[t] == 0.0) continue;
    double s = 0.0;
    Vec3 u;
    relative_velocity(x, static_cast<int>(t), s, u);
    const Vec3& n = normal_[t];
    const double ut = u.norm();
    Eigen::Matrix3d block = 2.0 * settings_.normal_drag * std::abs(s) * (n * n.transpose());
    if (ut > 0.0) {
      block += settings_.tangential_drag *
               (ut * (Eigen::Matrix3d::Identity() - n * n.transpose()) + u * u.transpose() / ut);
    }
    block *= settings_.density * area_[t] / (18.0 * h_);
    // Every pair of corners gets the same block: the 9x9 Hessian is (1 1 1)^T (1 1 1) x block.
    const auto& tri = triangles_[t];
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) blocks.push_back({tri[i], tri[j], block});
    }
  }
}

}  // namespace animkit
