#include "animkit/cloth/particle_incidence.h"

#include <cstddef>

namespace animkit {

namespace {

// Compressed rows by counting sort: `ends(e)` lists element e's particles; entries are
// arity * e + slot, in increasing e for every particle.
template <std::size_t Arity, class Elements>
void build_rows(int particles, const Elements& elements, std::vector<int>& start,
                std::vector<int>& entry) {
  start.assign(static_cast<std::size_t>(particles) + 1, 0);
  for (const auto& element : elements) {
    for (int p : element) ++start[static_cast<std::size_t>(p) + 1];
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(particles); ++i) start[i + 1] += start[i];
  entry.resize(static_cast<std::size_t>(start.back()));
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t e = 0; e < elements.size(); ++e) {
    for (std::size_t slot = 0; slot < Arity; ++slot) {
      const auto p = static_cast<std::size_t>(elements[e][slot]);
      entry[static_cast<std::size_t>(fill[p]++)] = static_cast<int>(Arity * e + slot);
    }
  }
}

}  // namespace

ParticleIncidence::ParticleIncidence(const ClothModel& model) {
  build_rows<2>(model.particle_count(), model.springs, spring_start, spring_entry);
  build_rows<3>(model.particle_count(), model.bends, bend_start, bend_entry);
}

}  // namespace animkit
