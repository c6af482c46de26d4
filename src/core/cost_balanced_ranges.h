#pragma once
// Contiguous ranges of items (bodies), one per thread, of about equal cost, where the cost of
// an item is the time it took at its last visit: a loop whose items keep their thread from one
// call to the next, unlike a dynamic schedule's, and stays balanced when the items' costs differ.
//
// Why: the step's loop over bodies (solver/node_update.cpp) writes each body's nodes; under a
// dynamic schedule about half the bodies changed thread from one step to the next, and their
// nodes moved between the cores' caches. On the 2-core machine of bench/results/debian12-2core
// that cost little while the machine was quiet and doubled the velocity phase when it was not
// (60-grain cell, corotational, 2 threads: 0.45 -> 1.0 s; with the ranges 0.37 -> 0.42 s);
// equal counts (a static schedule) made the objective model's uneven solves 4-6% slower.
//
// Which thread runs an item changes the time a loop takes, never its results: the items are
// independent and their results are kept per item.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

namespace sg {

class CostBalancedRanges {
 public:
  // The number of items; their costs are kept while it does not change (before the first
  // visit of every item, the ranges hold equal numbers of items).
  void resize(std::size_t items) {
    if (items != cost_.size()) cost_.assign(items, kUnknown);
  }

  // The ranges of `threads` threads: thread t's is [start(t), start(t + 1)). Called by one
  // thread before any next() (outside the loop's parallel region, or in an omp single).
  void plan(int threads) {
    starts_.assign(static_cast<std::size_t>(threads) + 1, cost_.size());
    starts_[0] = 0;
    const bool known = std::none_of(cost_.begin(), cost_.end(), [](double c) { return c < 0.0; });
    const auto cost = [&](std::size_t i) { return known ? cost_[i] : 1.0; };
    double total = 0.0;
    for (std::size_t i = 0; i < cost_.size(); ++i)
      total += cost(i);
    double sum = 0.0;
    int thread = 1;
    for (std::size_t i = 0; i < cost_.size() && thread < threads; ++i) {
      // Item i goes to the thread whose share its cost's midpoint falls in.
      while (thread < threads && sum + 0.5 * cost(i) > total * thread / threads)
        starts_[static_cast<std::size_t>(thread++)] = i;
      sum += cost(i);
    }
    cursors_.assign(static_cast<std::size_t>(threads) * kCursorStride, 0);
    for (int t = 0; t < threads; ++t)
      cursors_[static_cast<std::size_t>(t) * kCursorStride] = starts_[static_cast<std::size_t>(t)];
  }
  std::pair<std::size_t, std::size_t> range(int thread) const {
    const auto t = static_cast<std::size_t>(thread);
    return {starts_[t], starts_[t + 1]};
  }

  // The next item for `thread` to run, or none() when every item has been taken: its own
  // range in order, then what is left of the next threads' ranges, taken from their fronts as
  // their own threads take them (a body whose cost jumped at this step, a rebuilt
  // preconditioner, leaves its thread behind: the others finish its range). Thread-safe: one
  // atomic counter per range, on a cache line of its own.
  std::size_t next(int thread) {
    const auto threads = static_cast<int>(starts_.size()) - 1;
    for (int k = 0; k < threads; ++k) {
      const auto r = static_cast<std::size_t>((thread + k) % threads);
      const std::size_t i = std::atomic_ref<std::size_t>(cursors_[r * kCursorStride]).fetch_add(1);
      if (i < starts_[r + 1]) return i;
    }
    return none();
  }
  static constexpr std::size_t none() { return static_cast<std::size_t>(-1); }

  // The time item i took at this visit (by the thread that ran it). A short running average,
  // so that one slow visit (a refactorization, an interruption) moves few items.
  void record(std::size_t i, double seconds) {
    cost_[i] = cost_[i] < 0.0 ? seconds : 0.5 * (cost_[i] + seconds);
  }

 private:
  static constexpr double kUnknown = -1.0;
  static constexpr std::size_t kCursorStride = 64 / sizeof(std::size_t);
  std::vector<double> cost_;
  std::vector<std::size_t> starts_;
  std::vector<std::size_t> cursors_;  // per range, the next item to take (atomic_ref)
};

}  // namespace sg
