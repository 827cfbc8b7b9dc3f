#include "../../src/core/thread_pool.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <set>
#include <thread>
#include <vector>

#include "../../src/core/parallel.h"

namespace animkit::parallel {
namespace {

// Every task of a loop runs exactly once, whatever the thread count and however loops follow
// one another (workers that wake late for a finished loop must not run the next one's tasks).
TEST(ThreadPool, EveryTaskRunsOnceInLoopAfterLoop) {
  std::vector<std::atomic<int>> runs(300);
  for (int round = 0; round < 2000; ++round) {
    const int tasks = 1 + (round * 37) % 300;
    const int threads = 1 + round % 4;
    for (int i = 0; i < tasks; ++i) runs[static_cast<std::size_t>(i)].store(0);
    auto task = [&](int i) { runs[static_cast<std::size_t>(i)].fetch_add(1); };
    run_tasks(tasks, threads, task);
    for (int i = 0; i < tasks; ++i)
      ASSERT_EQ(runs[static_cast<std::size_t>(i)].load(), 1) << "round " << round << " task " << i;
  }
}

// With two threads a pool worker takes part: tasks that sleep leave the worker time to wake
// and claim some, whatever else the machine runs.
TEST(ThreadPool, AWorkerTakesPartInALoopOfLongTasks) {
  std::vector<std::thread::id> ran_on(40);
  auto task = [&](int i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    ran_on[static_cast<std::size_t>(i)] = std::this_thread::get_id();
  };
  run_tasks(40, 2, task);
  std::set<std::thread::id> threads(ran_on.begin(), ran_on.end());
  EXPECT_EQ(threads.size(), 2u);
  EXPECT_TRUE(threads.count(std::this_thread::get_id()) == 1);  // the caller works too
}

// A loop inside a task (the pool already running) runs on that task's thread, whole.
TEST(ThreadPool, ALoopInsideATaskRunsWhole) {
  std::vector<std::atomic<int>> inner(64 * 50);
  auto outer = [&](int o) {
    auto task = [&](int i) { inner[static_cast<std::size_t>(o * 50 + i)].fetch_add(1); };
    run_tasks(50, 2, task);
  };
  run_tasks(64, 2, outer);
  for (const auto& count : inner) EXPECT_EQ(count.load(), 1);
}

// Two threads running loops at once (two simulations): each loop is whole; one of them gets
// the pool, the other runs on its own thread.
TEST(ThreadPool, LoopsFromTwoThreadsAtOnceAreEachWhole) {
  constexpr int kTasks = 200, kRounds = 300;
  auto run = [](std::vector<int>& runs) {
    for (int round = 0; round < kRounds; ++round) {
      std::vector<std::atomic<int>> counts(kTasks);
      auto task = [&](int i) { counts[static_cast<std::size_t>(i)].fetch_add(1); };
      run_tasks(kTasks, 2, task);
      for (const auto& c : counts) runs.push_back(c.load());
    }
  };
  std::vector<int> a, b;
  std::thread other([&] { run(b); });
  run(a);
  other.join();
  ASSERT_EQ(a.size(), static_cast<std::size_t>(kTasks * kRounds));
  ASSERT_EQ(b.size(), a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i], 1);
    ASSERT_EQ(b[i], 1);
  }
}

// A child forked after the pool started (Python's multiprocessing) has the pool's state but
// not its threads: its loops still run whole, on its own thread.
TEST(ThreadPool, AForkedChildRunsItsLoopsWhole) {
  std::atomic<int> parent_runs{0};
  auto count = [&](int) { parent_runs.fetch_add(1); };
  run_tasks(100, 2, count);  // the worker exists now
  ASSERT_EQ(parent_runs.load(), 100);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::vector<int> runs(1000, 0);
    auto task = [&](int i) { ++runs[static_cast<std::size_t>(i)]; };
    for (int round = 0; round < 10; ++round) run_tasks(1000, 2, task);
    for (int r : runs)
      if (r != 10) _exit(1);
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

// A sum over chunks comes out the same bits for one and for several threads: the chunks are
// added in order, whichever thread ran each.
TEST(ThreadPool, ChunkedSumIsTheSameForAnyThreadCount) {
  const int count = 100'003;
  std::vector<std::array<double, 1>> partials(static_cast<std::size_t>(chunk_count(count)));
  auto term = [](int i, std::array<double, 1>& acc) { acc[0] += 1.0 / (1.0 + i * 0.37); };
  set_thread_count(1);
  const double one = sum<1>(count, partials, term)[0];
  for (int threads : {2, 3, 4}) {
    set_thread_count(threads);
    EXPECT_EQ(sum<1>(count, partials, term)[0], one) << threads << " threads";
  }
  set_thread_count(0);
}

}  // namespace
}  // namespace animkit::parallel
