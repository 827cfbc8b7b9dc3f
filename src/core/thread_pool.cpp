#include "thread_pool.h"

#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <climits>
#include <cstdint>
#include <mutex>
#include <thread>

namespace animkit::parallel {

namespace {

// How long a worker keeps watching for the next loop before it sleeps: a Newton iteration's
// conjugate gradients run one short loop after another (tens of microseconds each), and waking
// a sleeping thread costs about as much as such a loop.
constexpr auto kWorkerSpin = std::chrono::microseconds(50);
// Spins of the caller waiting for a worker's last task before it yields its core to it.
constexpr int kCallerSpins = 2000;

// A worker sleeps until a loop is announced in a futex wait on the epoch, and the caller wakes
// it only when a worker is counted asleep: while the workers spin between the short loops of
// one Newton iteration, announcing a loop costs no system call.
// https://man7.org/linux/man-pages/man2/futex.2.html
void futex_wait(std::atomic<std::uint32_t>& word, std::uint32_t expected) {
  static_assert(sizeof(std::atomic<std::uint32_t>) == sizeof(std::uint32_t));
  syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAIT_PRIVATE, expected, nullptr,
          nullptr, 0);
}
void futex_wake_all(std::atomic<std::uint32_t>& word) {
  syscall(SYS_futex, reinterpret_cast<std::uint32_t*>(&word), FUTEX_WAKE_PRIVATE, INT_MAX, nullptr,
          nullptr, 0);
}

inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#else
  std::this_thread::yield();
#endif
}

// The loop being run is published in `next_`: its generation in the high 32 bits, the next
// unclaimed task in the low 32. A task is claimed by a compare-exchange that keeps the
// generation, so it can only be claimed while its loop is the current one. When every task of
// a loop has finished, the caller closes the loop (low bits all ones: no index is below that)
// before it writes the next loop's task: a worker that read a later loop's task but the older
// generation then fails every claim, since the older loop never reopens.
class Pool {
 public:
  // Never destroyed: the workers sleep until the process ends, so nothing is torn down while
  // another static's destructor might still run a loop, and a process forked from this one
  // (Python's multiprocessing), which has the pool but not its threads, runs every loop on its
  // calling thread, whole (no task waits for a worker).
  static Pool& instance() {
    static Pool* const pool = new Pool;
    return *pool;
  }

  void run(int tasks, int threads, TaskRef task) {
    // A loop inside one of this thread's tasks: the pool is this thread's already.
    thread_local bool running_a_loop = false;
    std::unique_lock lock(busy_, std::defer_lock);
    if (running_a_loop || !lock.try_lock()) {
      for (int i = 0; i < tasks; ++i) task.call(task.context, i);
      return;
    }
    running_a_loop = true;
    start_workers(threads - 1);
    helpers_.store(threads - 1);
    task_context_.store(task.context);
    task_call_.store(task.call);
    task_count_.store(tasks);
    done_.store(0);
    const std::uint64_t generation = ++generation_;
    next_.store(generation << 32);
    epoch_.fetch_add(1);
    // A worker counts itself asleep before it checks the epoch a last time, so either it sees
    // this epoch or this sees it asleep (every access sequentially consistent).
    if (sleepers_.load() > 0) futex_wake_all(epoch_);

    int mine = 0, index = 0;
    while (claim(generation, tasks, index)) {
      task.call(task.context, index);
      ++mine;
    }
    done_.fetch_add(mine);
    for (int spins = 0; done_.load() != tasks; ++spins) {
      if (spins < kCallerSpins) {
        relax();
      } else {
        std::this_thread::yield();
      }
    }
    next_.store((generation << 32) | kClosed);
    running_a_loop = false;
  }

 private:
  static constexpr std::uint64_t kClosed = 0xffffffffu;

  bool claim(std::uint64_t generation, int tasks, int& index) {
    std::uint64_t v = next_.load();
    while (true) {
      if ((v >> 32) != generation) return false;
      const std::uint64_t i = v & kClosed;
      if (i >= static_cast<std::uint64_t>(tasks)) return false;
      if (next_.compare_exchange_weak(v, v + 1)) {
        index = static_cast<int>(i);
        return true;
      }
    }
  }

  // Under busy_, before the loop is announced: a new worker starts from the epoch before the
  // announcement, so it takes part in the loop that started it.
  void start_workers(int count) {
    for (; workers_ < count; ++workers_) {
      const int id = workers_;
      const std::uint32_t seen = epoch_.load();
      std::thread([this, id, seen] { work(id, seen); }).detach();
    }
  }

  [[noreturn]] void work(int id, std::uint32_t seen) {
    while (true) {
      const auto spin_end = std::chrono::steady_clock::now() + kWorkerSpin;
      while (epoch_.load() == seen && std::chrono::steady_clock::now() < spin_end) relax();
      sleepers_.fetch_add(1);
      while (epoch_.load() == seen) futex_wait(epoch_, seen);  // returns at once if changed
      sleepers_.fetch_sub(1);
      seen = epoch_.load();
      if (id >= helpers_.load()) continue;
      const std::uint64_t generation = next_.load() >> 32;
      void* const context = task_context_.load();
      void (*const call)(void*, int) = task_call_.load();
      const int tasks = task_count_.load();
      int mine = 0, index = 0;
      while (claim(generation, tasks, index)) {
        call(context, index);
        ++mine;
      }
      if (mine > 0) done_.fetch_add(mine);
    }
  }

  std::mutex busy_;               // one loop at a time; held by the loop's caller
  int workers_ = 0;               // started so far, ids 0 .. workers_ - 1
  std::uint64_t generation_ = 0;  // the caller's count of loops (under busy_)
  std::atomic<std::uint64_t> next_{kClosed};
  std::atomic<std::uint32_t> epoch_{0};  // bumped to wake the workers
  std::atomic<int> sleepers_{0};         // workers in (or about to enter) futex_wait
  std::atomic<int> helpers_{0};          // workers with an id below this take part
  std::atomic<void*> task_context_{nullptr};
  std::atomic<void (*)(void*, int)> task_call_{nullptr};
  std::atomic<int> task_count_{0};
  std::atomic<int> done_{0};
};

}  // namespace

void run_tasks(int tasks, int threads, TaskRef task) {
  if (tasks <= 0) return;
  if (threads <= 1 || tasks == 1) {
    for (int i = 0; i < tasks; ++i) task.call(task.context, i);
    return;
  }
  Pool::instance().run(tasks, threads, task);
}

}  // namespace animkit::parallel
