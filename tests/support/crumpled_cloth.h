#pragma once
// A cloth crumpled at random with every spring keeping its flat rest length, so the first
// steps start far from equilibrium, with springs compressed and stretched hard: the scene that
// makes line searches and local guards work. Deterministic (fixed seed).
#include <random>

#include "animkit/cloth/cloth_model.h"

namespace animkit::testing_support {

inline ClothDesc crumpled(ClothDesc desc) {
  for (SpringDesc& s : desc.springs) {
    s.rest_length = (desc.particles[s.a].position - desc.particles[s.b].position).norm();
  }
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (ParticleDesc& p : desc.particles) {
    if (!p.pinned) p.position += Vec3(u(rng), u(rng), u(rng));
  }
  return desc;
}

}  // namespace animkit::testing_support
