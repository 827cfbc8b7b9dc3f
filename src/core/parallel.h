#pragma once
// Deterministic parallel loops over flat arrays (OpenMP), for the cloth solvers' hot loops.
//
// Two rules keep the results independent of the thread count (and so the same bits run after
// run): a parallel loop writes each output element from exactly one iteration (scatters such
// as "add a spring's force to both its particles" become a per-spring pass into a buffer and
// a per-particle gather over a fixed incidence list), and a sum is split into fixed chunks of
// kChunk terms, each summed in order, the chunk totals then added in chunk order. A sum of at
// most kChunk terms is therefore the plain sequential sum.
//
// Loops below kMinParallelWork iterations run on the calling thread: a parallel region costs
// a few microseconds to start, more than a small model's whole loop.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "animkit/core/threads.h"

namespace animkit::parallel {

inline constexpr int kChunk = 1024;
inline constexpr int kMinParallelWork = 4096;

/// Threads for a loop of `work` iterations: 1 below kMinParallelWork.
inline int threads_for(int work) {
  return work < kMinParallelWork ? 1 : thread_count();
}

inline int chunk_count(int count) {
  return (count + kChunk - 1) / kChunk;
}

/// f(i) for i in [0, count), statically split over the threads.
template <class F>
void for_each(int count, F&& f) {
  const int threads = threads_for(count);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int i = 0; i < count; ++i) f(i);
}

/// Per chunk of kChunk indices, a few sums in fixed order: f(i, acc) adds index i's terms to
/// `acc`. `partials` is the caller's workspace with chunk_count(count) entries (sized once).
/// Returns the chunk totals added in chunk order.
template <std::size_t N, class F>
std::array<double, N> sum(int count, std::vector<std::array<double, N>>& partials, F&& f) {
  const int chunks = chunk_count(count);
  const int threads = threads_for(count);
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1)
  for (int c = 0; c < chunks; ++c) {
    std::array<double, N> acc{};
    const int end = std::min(count, (c + 1) * kChunk);
    for (int i = c * kChunk; i < end; ++i) f(i, acc);
    partials[static_cast<std::size_t>(c)] = acc;
  }
  std::array<double, N> total{};
  for (int c = 0; c < chunks; ++c) {
    for (std::size_t k = 0; k < N; ++k) total[k] += partials[static_cast<std::size_t>(c)][k];
  }
  return total;
}

}  // namespace animkit::parallel
