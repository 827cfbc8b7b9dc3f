#include "animkit/cloth/cloth_model.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "animkit/cloth/bend_energy.h"
#include "animkit/cloth/parameter_ranges.h"
#include "animkit/cloth/spring_energy.h"
#include "animkit/core/validation.h"

namespace animkit {

namespace {
std::string particle(std::size_t i) {
  return "particle " + std::to_string(i);
}
std::string spring(std::size_t i) {
  return "spring " + std::to_string(i);
}
bool finite_positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

// A spring's rest length: as given, or (negative) the distance of its particles as described.
double resolved_rest_length(const ClothDesc& desc, const SpringDesc& s) {
  return s.rest_length >= 0.0
             ? s.rest_length
             : (desc.particles[s.a].position - desc.particles[s.b].position).norm();
}
}  // namespace

std::optional<Error> ClothDesc::validate() const {
  if (particles.empty()) return Error{"the cloth has no particles"};
  if (!kGravityRange.contains(gravity)) return Error{kGravityRange.refusal("gravity", gravity)};
  if (!kDampingRange.contains(damping)) return Error{kDampingRange.refusal("damping", damping)};
  const auto within = [](const ParameterRange& range, const Vec3& v) {
    return range.contains(v.x()) && range.contains(v.y()) && range.contains(v.z());
  };
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const ParticleDesc& p = particles[i];
    if (!is_finite(p.position)) return Error{particle(i) + " has a non-finite position"};
    if (!is_finite(p.velocity)) return Error{particle(i) + " has a non-finite velocity"};
    if (!within(kCoordinateRange, p.position)) {
      return Error{particle(i) + " position " + to_string(p.position) + " is beyond +-" +
                   format_number(kCoordinateRange.max)};
    }
    if (!within(kSpeedRange, p.velocity)) {
      return Error{particle(i) + " velocity " + to_string(p.velocity) + " is beyond +-" +
                   format_number(kSpeedRange.max)};
    }
    if (!kMassRange.contains(p.mass))
      return Error{kMassRange.refusal(particle(i) + " mass", p.mass)};
  }
  const int n = static_cast<int>(particles.size());
  for (std::size_t s = 0; s < springs.size(); ++s) {
    const SpringDesc& sp = springs[s];
    if (sp.a < 0 || sp.a >= n || sp.b < 0 || sp.b >= n) {
      return Error{spring(s) + " joins particles " + std::to_string(sp.a) + " and " +
                   std::to_string(sp.b) + ", but there are " + std::to_string(n)};
    }
    if (sp.a == sp.b) {
      return Error{spring(s) + " joins particle " + std::to_string(sp.a) + " to itself"};
    }
    if (!kStiffnessRange.contains(sp.stiffness)) {
      return Error{kStiffnessRange.refusal(spring(s) + " stiffness", sp.stiffness)};
    }
    const double length = resolved_rest_length(*this, sp);
    if (!finite_positive(length)) {
      return Error{spring(s) + " has zero rest length"};
    }
  }
  for (std::size_t k = 0; k < bends.size(); ++k) {
    const BendDesc& b = bends[k];
    const std::string name = "bend " + std::to_string(k);
    const int size = b.particles[3] < 0 ? 3 : 4;
    double sum = 0.0, magnitude = 0.0;
    for (int i = 0; i < 4; ++i) {
      const int v = b.particles[i];
      if (i < size && (v < 0 || v >= n))
        return Error{name + " has no particle " + std::to_string(v)};
      for (int j = 0; j < i && i < size; ++j) {
        if (b.particles[j] == v)
          return Error{name + " joins particle " + std::to_string(v) + " to itself"};
      }
      if (!std::isfinite(b.weights[i])) return Error{name + " has a non-finite weight"};
      if (i >= size && b.weights[i] != 0.0)
        return Error{name + " has a weight on its unused fourth slot"};
      sum += b.weights[i];
      magnitude += std::abs(b.weights[i]);
    }
    // The Hessian's spring-block form (bend_energy.h) needs sum w = 0, and so does invariance
    // under translation.
    if (!(std::abs(sum) <= 1e-9 * magnitude)) {
      return Error{name + " weights sum to " + format_number(sum) + ", not zero"};
    }
    if (!kStiffnessRange.contains(b.stiffness)) {
      return Error{kStiffnessRange.refusal(name + " stiffness", b.stiffness)};
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    for (int v : triangles[t]) {
      if (v < 0 || v >= n)
        return Error{"triangle " + std::to_string(t) + " has no particle " + std::to_string(v)};
    }
  }
  return std::nullopt;
}

Result<BuiltCloth> build_cloth(const ClothDesc& desc) {
  if (auto error = desc.validate()) return fail(error->message);
  BuiltCloth built;
  ClothModel& m = built.model;
  const std::size_t n = desc.particles.size();
  built.state.positions.resize(3 * static_cast<Eigen::Index>(n));
  built.state.velocities.resize(3 * static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i) {
    const ParticleDesc& p = desc.particles[i];
    m.mass.push_back(p.mass);
    m.pinned.push_back(p.pinned ? 1 : 0);
    built.state.positions.segment<3>(3 * static_cast<Eigen::Index>(i)) = p.position;
    // A pinned particle never moves, whatever velocity it was described with.
    built.state.velocities.segment<3>(3 * static_cast<Eigen::Index>(i)) =
        p.pinned ? Vec3::Zero() : p.velocity;
  }
  for (const SpringDesc& s : desc.springs) {
    m.springs.push_back({s.a, s.b});
    m.rest_length.push_back(resolved_rest_length(desc, s));
    m.stiffness.push_back(s.stiffness);
  }
  // Each bend's three pairs, found among the springs or added as coupling-only springs.
  std::map<std::pair<int, int>, int> spring_of;
  for (int s = 0; s < m.spring_count(); ++s) {
    const auto [a, b] = m.springs[s];
    spring_of.emplace(std::minmax(a, b), s);
  }
  const auto spring_joining = [&](int a, int b) {
    const auto [it, added] = spring_of.emplace(std::minmax(a, b), m.spring_count());
    if (added) {
      m.springs.push_back({a, b});
      m.rest_length.push_back((desc.particles[a].position - desc.particles[b].position).norm());
      m.stiffness.push_back(0.0);
    }
    return it->second;
  };
  for (const BendDesc& b : desc.bends) {
    m.bends.push_back(b.particles);
    m.bend_weights.push_back(b.weights);
    m.bend_stiffness.push_back(b.stiffness);
    std::array<int, 6> springs{-1, -1, -1, -1, -1, -1};
    for (std::size_t q = 0; q < kBendPairs.size(); ++q) {
      const int i = b.particles[kBendPairs[q][0]], j = b.particles[kBendPairs[q][1]];
      if (i >= 0 && j >= 0) springs[q] = spring_joining(i, j);
    }
    m.bend_springs.push_back(springs);
  }
  m.triangles = desc.triangles;
  m.gravity = desc.gravity;
  m.damping = desc.damping;
  return built;
}

ClothEnergy cloth_energy(const ClothModel& model, const ClothState& state) {
  ClothEnergy e;
  for (int i = 0; i < model.particle_count(); ++i) {
    e.kinetic += 0.5 * model.mass[i] * state.velocity(i).squaredNorm();
    e.gravitational += model.mass[i] * model.gravity * state.positions[3 * i + 1];
  }
  for (int s = 0; s < model.spring_count(); ++s) {
    const auto [a, b] = model.springs[s];
    e.elastic += spring_energy(state.position(a), state.position(b), model.stiffness[s],
                               model.rest_length[s]);
  }
  for (int k = 0; k < model.bend_count(); ++k) {
    e.elastic += bend_energy(state.positions, model.bends[k], model.bend_weights[k],
                             model.bend_stiffness[k]);
  }
  e.total = e.kinetic + e.elastic + e.gravitational;
  return e;
}

}  // namespace animkit
