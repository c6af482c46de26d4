#pragma once
// Parallel loops over independent items (bodies) with OpenMP, where an exception thrown by
// one item must not terminate the program: the error of the lowest failing index is
// rethrown after the loop, so the message does not depend on the thread count either.
#include <cstddef>
#include <exception>
#include <limits>
#include <utility>

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

// The error of the lowest failing index of a parallel loop, so that the message does not
// depend on the thread count: record() in the loop's catch block, rethrow_if_any() after it.
class LowestIndexError {
 public:
  void record(int index, std::exception_ptr error) {
#pragma omp critical(sg_lowest_index_error)
    if (index < index_) {
      index_ = index;
      error_ = std::move(error);
    }
  }
  void rethrow_if_any() const {
    if (error_) std::rethrow_exception(error_);
  }

 private:
  int index_ = std::numeric_limits<int>::max();
  std::exception_ptr error_;
};

template <typename Body>
void parallel_for(int count, Body&& body) {
  LowestIndexError error;
#pragma omp parallel for schedule(dynamic, 4)
  for (int i = 0; i < count; ++i) {
    try {
      body(i);
    } catch (...) {
      error.record(i, std::current_exception());
    }
  }
  error.rethrow_if_any();
}

}  // namespace sg
