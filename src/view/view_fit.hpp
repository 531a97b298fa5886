// Private: the fit a page starts (view.hpp, startViewFit), shared by the scene's copies.
#pragma once

#include <atomic>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "sphereset/sphere.hpp"
#include "sphereset/status.hpp"
#include "sphereset/view.hpp"

namespace sphereset {

struct ViewFitJob {
  std::vector<int64_t> solids;  // the solids it replaces, in the scene's order
  std::atomic<bool> cancel{false};
  std::mutex mutex;  // guards what follows
  std::string state = "running";
  double fraction = 0.0;
  std::string stage = "starting";
  std::string error;
  std::vector<std::vector<Sphere>> sets;  // per entry of `solids`, when done
  std::map<std::string, int> counts;
  bool applied = false;
  std::thread thread;  // last: started once everything above is set

  ViewFitJob() = default;
  ViewFitJob(const ViewFitJob&) = delete;
  ViewFitJob& operator=(const ViewFitJob&) = delete;
  // Cancels and waits: a scene (and the server holding it) never outlives its fit's thread.
  ~ViewFitJob();
};

// kInvalidArgument when a running fit will replace `solid`'s set (an edit, a bound or a level
// change would be lost): the edits' functions refuse with it.
Status checkNotFitting(const ViewScene& scene, int64_t solid);

}  // namespace sphereset
