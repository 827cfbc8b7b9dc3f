#pragma once
// Deterministic parallel loops over flat arrays (on thread_pool.h), for the cloth solvers' hot
// loops.
//
// Three rules keep the results independent of the thread count (and so the same bits run after
// run): a parallel loop writes each output element from exactly one iteration; scatters such
// as "add a spring's force to both its particles" follow an ElementSchedule (see
// animkit/cloth/element_schedule.h), whose segments running at once touch disjoint particles;
// and a sum is split into fixed chunks of kChunk terms, each summed in order, the chunk totals
// then added in chunk order. A sum of at most kChunk terms is therefore the plain sequential
// sum.
//
// Loops below kMinParallelWork iterations run on the calling thread, without the pool at all:
// a hand-off to other threads costs more than such a loop (a step of the lab's 11 x 11 cloth
// runs some forty of them in about 50 microseconds). Larger loops are cut into tasks the
// calling thread and the pool's workers claim one at a time (thread_pool.h), so a worker that
// another process holds off its core never holds up the loop.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "animkit/core/threads.h"
#include "thread_pool.h"

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

/// f(i) for i in [0, count), in tasks of kChunk indices.
template <class F>
void for_each(int count, F&& f) {
  const int threads = threads_for(count);
  if (threads == 1) {
    for (int i = 0; i < count; ++i) f(i);
    return;
  }
  auto task = [&](int c) {
    const int end = std::min(count, (c + 1) * kChunk);
    for (int i = c * kChunk; i < end; ++i) f(i);
  };
  run_tasks(chunk_count(count), threads, task);
}

/// for_each for loops whose iterations each cost about `weight` (>= 1) light iterations (a
/// contact pair's barrier and its 12 x 12 eigendecomposition): parallel from kMinParallelWork /
/// weight iterations on, in tasks of about kChunk light iterations.
template <class F>
void for_each_weighted(int count, int weight, F&& f) {
  const long work = static_cast<long>(count) * weight;
  const int threads = work < kMinParallelWork ? 1 : thread_count();
  if (threads == 1) {
    for (int i = 0; i < count; ++i) f(i);
    return;
  }
  const int size = std::max(1, kChunk / weight);
  auto task = [&](int c) {
    const int end = std::min(count, (c + 1) * size);
    for (int i = c * size; i < end; ++i) f(i);
  };
  run_tasks((count + size - 1) / size, threads, task);
}

/// f(e) for every element of `schedule` (an ElementSchedule): its even segments, then its odd
/// ones, each segment in order; the segments of one parity run as separate tasks when the
/// schedule allows it.
template <class Schedule, class F>
void scatter(const Schedule& schedule, F&& f) {
  const int threads = schedule.parallel ? threads_for(schedule.size()) : 1;
  const int* order = schedule.order.data();
  const int* start = schedule.segment_start.data();
  constexpr int segments = Schedule::kSegments;
  for (int phase = 0; phase < 2; ++phase) {
    auto segment = [&](int t) {
      const int s = phase + 2 * t;
      for (int k = start[s]; k < start[s + 1]; ++k) f(order[k]);
    };
    const int count = (segments - phase + 1) / 2;
    if (threads == 1) {
      for (int t = 0; t < count; ++t) segment(t);
    } else {
      run_tasks(count, threads, segment);
    }
  }
}

/// Per chunk of kChunk indices, a few sums in fixed order: f(i, acc) adds index i's terms to
/// `acc`. `partials` is the caller's workspace with chunk_count(count) entries (sized once).
/// Returns the chunk totals added in chunk order.
template <std::size_t N, class F>
std::array<double, N> sum(int count, std::vector<std::array<double, N>>& partials, F&& f) {
  const int chunks = chunk_count(count);
  const auto chunk_sum = [&](int c) {
    std::array<double, N> acc{};
    const int end = std::min(count, (c + 1) * kChunk);
    for (int i = c * kChunk; i < end; ++i) f(i, acc);
    partials[static_cast<std::size_t>(c)] = acc;
  };
  const int threads = threads_for(count);
  if (threads == 1) {
    for (int c = 0; c < chunks; ++c) chunk_sum(c);
  } else {
    run_tasks(chunks, threads, chunk_sum);
  }
  std::array<double, N> total{};
  for (int c = 0; c < chunks; ++c) {
    for (std::size_t k = 0; k < N; ++k) total[k] += partials[static_cast<std::size_t>(c)][k];
  }
  return total;
}

}  // namespace animkit::parallel
