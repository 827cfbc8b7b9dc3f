#pragma once
// The threads behind the parallel loops (parallel.h): the calling thread and a few pool workers
// share a loop's tasks by claiming them one at a time from a shared counter. The caller never
// waits for a worker to start: it claims tasks itself from the first, and a worker that is
// asleep, or preempted by another process, simply claims none, so the loop then takes what one
// thread takes. It waits only for tasks a worker has already begun. OpenMP's static loops
// instead hand each thread its share up front and end at a barrier, where the caller waits for
// a thread the operating system has not scheduled yet: on a machine with another busy process,
// two threads ran the cloth solvers several times slower than one.
//
// One loop runs on the pool at a time: a loop that finds the pool busy (another thread's
// simulation, or a loop inside a task) runs on its own thread alone.

namespace animkit::parallel {

/// A task function: call(context, i) runs task i.
struct TaskRef {
  void* context = nullptr;
  void (*call)(void*, int) = nullptr;
};

/// Runs every task i in [0, tasks) exactly once, on the calling thread and up to threads - 1
/// pool workers; returns when all have finished. Tasks may run in any order and at once, so
/// each must write only its own outputs.
void run_tasks(int tasks, int threads, TaskRef task);

/// run_tasks for a callable f(int) (a lambda: its call operator is const).
template <class F>
void run_tasks(int tasks, int threads, const F& f) {
  run_tasks(tasks, threads,
            TaskRef{const_cast<void*>(static_cast<const void*>(&f)),
                    [](void* f_, int i) { (*static_cast<const F*>(f_))(i); }});
}

}  // namespace animkit::parallel
