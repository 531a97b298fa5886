// How fitRobot runs its work per link: one task per link, each parallel inside except for its
// repair (the wrap is single-threaded), and the steps reported as the links finish them.
#pragma once
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <mutex>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "sphereset/robot_fit.hpp"

namespace sphereset::detail {

// RobotFitOptions::steps, one call at a time, counting the units done.
class StepReporter {
 public:
  StepReporter(const RobotFitOptions& o, std::string stage, int64_t total)
      : o_(o), stage_(std::move(stage)), total_(total) {}
  void done(const std::string& link) {
    if (!o_.steps) return;
    std::lock_guard<std::mutex> lock(mutex_);
    o_.steps(RobotProgress{stage_, ++done_, total_, link});
  }

 private:
  const RobotFitOptions& o_;
  std::string stage_;
  int64_t total_, done_ = 0;
  std::mutex mutex_;
};

// Calls f(i) once for every i in [0, cost.size()), in parallel, starting the largest cost first
// (ties in index order): longest processing time first. A parallel_for over the links in the
// robot's order splits them into halves, so the largest link may start last and leave the other
// cores idle at the end of the stage; here the links come from one queue, taken by as many
// workers as the arena has. Each call runs isolated, so that a worker waiting inside one link's
// parallel loops does not take up the queue's other links. When a call throws (a cancellation
// from a progress callback), no further link is started and the first exception propagates.
// The order changes only when each link is done, not what is computed.
template <class F>
void forEachLargestFirst(const std::vector<double>& cost, F&& f) {
  std::vector<size_t> order(cost.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return cost[a] > cost[b]; });
  std::atomic<size_t> next{0};
  std::atomic<bool> stop{false};
  const int workers =
      std::max(1, std::min(tbb::this_task_arena::max_concurrency(), static_cast<int>(cost.size())));
  tbb::parallel_for(0, workers, 1, [&](int) {
    for (size_t k = next++; k < order.size() && !stop; k = next++) {
      try {
        tbb::this_task_arena::isolate([&] { f(order[k]); });
      } catch (...) {
        stop = true;
        throw;
      }
    }
  });
}

}  // namespace sphereset::detail
