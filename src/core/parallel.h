#pragma once
// Parallel loops over independent items (bodies) with OpenMP, where an exception thrown by
// one item must not terminate the program: the error of the lowest failing index is
// rethrown after the loop, so the message does not depend on the thread count either.
#include <exception>
#include <limits>

namespace sg {

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
