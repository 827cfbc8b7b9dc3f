#include "animkit/core/threads.h"

#include <omp.h>

#include <atomic>
#include <cassert>

namespace animkit {

namespace {
// 0: OpenMP's own default (OMP_NUM_THREADS, else the cores). A process-wide setting rather
// than omp_set_num_threads(), which only changes the calling thread's own default.
std::atomic<int> requested_threads{0};
}  // namespace

void set_thread_count(int count) {
  assert(count >= 0);
  requested_threads.store(count < 0 ? 0 : count, std::memory_order_relaxed);
}

int thread_count() {
  const int requested = requested_threads.load(std::memory_order_relaxed);
  return requested > 0 ? requested : omp_get_max_threads();
}

}  // namespace animkit
