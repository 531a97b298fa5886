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
  std::atomic<bool> cancel{false};
  std::mutex mutex;  // guards what follows
  // What viewFitStatus answers (status.solids: the solids it replaces, in the scene's order);
  // status.applied stays false here, `applied` says whether a status applied it.
  ViewFitStatus status;
  std::vector<std::vector<Sphere>> sets;  // per entry of status.solids, when done
  bool applied = false;
  std::thread thread;  // last: started once everything above is set

  ViewFitJob() {
    status.state = "running";
    status.stage = "starting";
  }
  ViewFitJob(const ViewFitJob&) = delete;
  ViewFitJob& operator=(const ViewFitJob&) = delete;
  // Cancels and waits: a scene (and the server holding it) never outlives its fit's thread.
  ~ViewFitJob();
};

// kInvalidArgument when a running fit will replace `solid`'s set (an edit, a bound or a level
// change would be lost): the edits' functions refuse with it.
Status checkNotFitting(const ViewScene& scene, int64_t solid);

}  // namespace sphereset
