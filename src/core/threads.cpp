#include "animkit/core/threads.h"

#include <atomic>
#include <cassert>
#include <cstdlib>
#include <thread>

namespace animkit {

namespace {
// 0: the default. A process-wide setting: set_thread_count() from any thread applies to
// every following loop.
std::atomic<int> requested_threads{0};

// OMP_NUM_THREADS when it starts with a positive count (as OpenMP programs read it: "2", or a
// list such as "2,1" whose first entry counts), else one thread per core. Read once.
int default_thread_count() {
  static const int count = [] {
    if (const char* text = std::getenv("OMP_NUM_THREADS")) {
      char* end = nullptr;
      const long n = std::strtol(text, &end, 10);
      if (end != text && n > 0 && n <= 1024) return static_cast<int>(n);
    }
    const unsigned cores = std::thread::hardware_concurrency();
    return cores > 0 ? static_cast<int>(cores) : 1;
  }();
  return count;
}
}  // namespace

void set_thread_count(int count) {
  assert(count >= 0);
  requested_threads.store(count < 0 ? 0 : count, std::memory_order_relaxed);
}

int thread_count() {
  const int requested = requested_threads.load(std::memory_order_relaxed);
  return requested > 0 ? requested : default_thread_count();
}

}  // namespace animkit
