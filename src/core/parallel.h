#pragma once
// Parallel loops over independent items (bodies) with OpenMP, where an exception thrown by
// one item must not terminate the program: the error of the lowest failing index is
// rethrown after the loop, so the message does not depend on the thread count either.
#include <cstddef>
#include <exception>
#include <limits>

namespace sg {

// Loops that stream a few numbers per contour point (their segments and tributary lengths,
// the broad phase's binning and rebuild test, a few dozen operations each) run in parallel
// only on models of at least this many points. A parallel region costs more than such a loop
// on fewer: waking sleeping threads (the passive wait policy, core/wait_policy.h) took about
// 40 us per region on the 2-core machine of bench/results/debian12-2core; a lone run's threads
// spin (a few us per region). At 10,000, the 60-grain cell's loops (a few thousand points, some
// 100 us each) were serial, and its contacts took 0.93-0.96 s of 3.4-3.5 s on 2 threads
// against 0.83-0.87 s in parallel (bench/results/debian12-2core/body_loop_speed.csv).
// (The nodes' own loops, gravity and the position update, are done body by body inside the
// step's loop over bodies: solver/node_update.cpp.)
inline constexpr std::size_t kParallelContourPoints = 1000;

template <typename Body>
void parallel_for(int count, Body&& body) {
  std::exception_ptr first_error;
  int first_index = std::numeric_limits<int>::max();
#pragma omp parallel for schedule(dynamic, 4)
  for (int i = 0; i < count; ++i) {
    try {
      body(i);
    } catch (...) {
#pragma omp critical(sg_parallel_for_error)
      if (i < first_index) {
        first_index = i;
        first_error = std::current_exception();
      }
    }
  }
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace sg
