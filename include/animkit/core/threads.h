#pragma once
// How many threads animkit's parallel loops use (src/core/thread_pool.h). The cloth solvers
// split their per-particle and per-spring loops over these threads; models too small to gain from
// it (the lab's 11 x 11 cloth) stay on the calling thread whatever the count.
//
// Results do not depend on the count: every parallel loop writes each output from one
// thread, in a fixed order of its inputs, and every sum is taken over fixed-size chunks added
// in chunk order (see src/core/parallel.h). So 1 and 2 threads give the same bits, and so do
// two runs.

namespace animkit {

/// Sets the number of threads for the following solver calls, from any thread. `count` >= 1;
/// 0 restores the default: OMP_NUM_THREADS when set, else one thread per core.
void set_thread_count(int count);

/// The number of threads the parallel loops use now (>= 1).
int thread_count();

}  // namespace animkit
