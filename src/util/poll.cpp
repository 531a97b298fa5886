// Cancellation polls from inside long loops (poll.hpp).
#include "util/poll.hpp"

#include <utility>

namespace sphereset::detail {
namespace {
thread_local PollScope* current_scope = nullptr;
}  // namespace

PollScope::PollScope(std::function<void()> callback, double interval)
    : callback_(std::move(callback)),
      interval_(interval),
      last_(std::chrono::steady_clock::now()),
      outer_(current_scope) {
  current_scope = this;
}

PollScope::~PollScope() { current_scope = outer_; }

void PollScope::restart() { last_ = std::chrono::steady_clock::now(); }

void PollScope::poll() {
  if (!callback_) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_).count() < interval_) return;
  last_ = now;
  callback_();
}

void pollCancel() {
  if (current_scope) current_scope->poll();
}

}  // namespace sphereset::detail
