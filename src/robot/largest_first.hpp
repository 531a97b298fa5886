// The links of a robot are prepared and fitted in parallel, one task per link, and each task is
// parallel inside except for its repair (the wrap is single-threaded). A parallel_for over the
// links in the robot's order splits them into halves, so the largest link may start last and
// leave the other cores idle at the end of the stage. Here the links are taken from one queue,
// the costliest first (longest processing time first), by as many workers as the arena has.
// The order changes only when each link is done, not what is computed: every link's result is
// its own.
#pragma once
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <numeric>
#include <vector>

namespace sphereset::detail {

// Calls f(i) once for every i in [0, cost.size()), in parallel, starting the largest cost first
// (ties in index order).
template <class F>
void forEachLargestFirst(const std::vector<double>& cost, F&& f) {
  std::vector<size_t> order(cost.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  std::atomic<size_t> next{0};
  const int workers =
      std::max(1, std::min(tbb::this_task_arena::max_concurrency(), static_cast<int>(cost.size())));
  tbb::parallel_for(0, workers, 1, [&](int) {
    for (size_t k = next++; k < order.size(); k = next++) f(order[k]);
  });
}

}  // namespace sphereset::detail
