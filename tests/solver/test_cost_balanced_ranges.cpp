#include "core/cost_balanced_ranges.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

namespace sg {
namespace {

// Before any visit the ranges hold equal numbers of items; once the items' times are recorded,
// about equal sums of time: one item as costly as the nine after it is a range of its own.
TEST(CostBalancedRanges, RangesAreContiguousAndBalancedByTheRecordedTimes) {
  CostBalancedRanges ranges;
  ranges.resize(10);
  ranges.plan(2);
  EXPECT_EQ(ranges.range(0), std::make_pair(std::size_t{0}, std::size_t{5}));
  EXPECT_EQ(ranges.range(1), std::make_pair(std::size_t{5}, std::size_t{10}));
  ranges.record(0, 9.0);
  for (std::size_t i = 1; i < 10; ++i)
    ranges.record(i, 1.0);
  ranges.plan(2);
  EXPECT_EQ(ranges.range(0), std::make_pair(std::size_t{0}, std::size_t{1}));
  EXPECT_EQ(ranges.range(1), std::make_pair(std::size_t{1}, std::size_t{10}));
  // Three threads: contiguous ranges that cover every item.
  ranges.plan(3);
  EXPECT_EQ(ranges.range(0).first, 0u);
  EXPECT_EQ(ranges.range(2).second, 10u);
  EXPECT_EQ(ranges.range(0).second, ranges.range(1).first);
  EXPECT_EQ(ranges.range(1).second, ranges.range(2).first);
  // Recorded times are averaged with the previous ones: one slow visit moves few items.
  ranges.record(0, 1.0);  // (9 + 1) / 2 = 5 against 9 others of 1
  ranges.plan(2);
  EXPECT_EQ(ranges.range(0), std::make_pair(std::size_t{0}, std::size_t{3}));
  // A new number of items: equal counts again.
  ranges.resize(4);
  ranges.plan(2);
  EXPECT_EQ(ranges.range(0), std::make_pair(std::size_t{0}, std::size_t{2}));
}

// Every item is handed out exactly once, whatever the threads' speeds: a thread that is done
// with its range takes what is left of the others'.
TEST(CostBalancedRanges, NextHandsOutEveryItemOnce) {
  CostBalancedRanges ranges;
  const std::size_t items = 1000;
  ranges.resize(items);
  for (const int threads : {1, 2, 3}) {
    std::vector<int> taken(items, 0);
#pragma omp parallel num_threads(threads)
    {
#pragma omp single
      ranges.plan(omp_get_num_threads());
      const int thread = omp_get_thread_num();
      for (std::size_t i = ranges.next(thread); i != CostBalancedRanges::none();
           i = ranges.next(thread))
        ++taken[i];
    }
    for (std::size_t i = 0; i < items; ++i)
      ASSERT_EQ(taken[i], 1) << "item " << i << ", " << threads << " threads";
  }
  // One thread takes its own range and then the rest, in order.
  ranges.plan(2);
  std::vector<std::size_t> order;
  for (std::size_t i = ranges.next(0); i != CostBalancedRanges::none(); i = ranges.next(0))
    order.push_back(i);
  ASSERT_EQ(order.size(), items);
  for (std::size_t i = 0; i < items; ++i)
    EXPECT_EQ(order[i], i);
}

}  // namespace
}  // namespace sg
