// Private: cancellation from inside long loops. A library call that can run long (a fit, an
// evaluation) holds a PollScope on its calling thread with its caller's callback; pollCancel(),
// called in the call's long loops, runs the callback from that thread once `interval` seconds
// have passed since the last run. On any other thread, or with no scope on this thread, it
// returns at once, so the loops may call it per item. The callback may throw (how the Python
// module turns Ctrl-C into KeyboardInterrupt): TBB cancels the loop the exception was raised in
// and rethrows it on the calling thread, and the call is abandoned.
#pragma once

#include <chrono>
#include <functional>

namespace sphereset::detail {

// Seconds between polls unless the call says otherwise.
inline constexpr double kPollSeconds = 0.25;

class PollScope {
 public:
  PollScope(std::function<void()> callback, double interval);
  ~PollScope();
  PollScope(const PollScope&) = delete;
  PollScope& operator=(const PollScope&) = delete;
  // The callback ran from outside the loops (an explicit report): the interval starts again.
  void restart();
  void poll();

 private:
  std::function<void()> callback_;
  double interval_;
  std::chrono::steady_clock::time_point last_;
  PollScope* outer_;  // the scope this one hides (a call made from inside another's callback)
};

void pollCancel();

}  // namespace sphereset::detail
