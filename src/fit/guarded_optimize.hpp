// Private: NLopt's optimisers with the objective's exceptions carried out. NLopt's C++ wrapper
// (nlopt.hpp, myfunc) catches every exception an objective throws, stops the optimiser and
// rethrows only a generic one of its own: a cancellation (Python's KeyboardInterrupt through
// the poll callback, a throwing progress callback) or std::bad_alloc would become "NLopt
// failure", which the fit treats as round-off and swallows. The objective runs through
// ObjectiveGuard::call, which stores the first exception and stops NLopt (nlopt::forced_stop);
// optimize() then rethrows that exception as it was. NLopt's own ends (round-off, a forced stop,
// evaluations used up) are normal: the caller keeps the best point evaluated.
#pragma once

#include <exception>
#include <nlopt.hpp>
#include <utility>
#include <vector>

namespace sphereset::detail {

class ObjectiveGuard {
 public:
  // f() as the objective's value; an exception it throws is kept and NLopt is stopped.
  template <class F>
  double call(F&& f) {
    struct Inside {
      Inside() { ++depth(); }
      ~Inside() { --depth(); }
    } inside;
    try {
      return std::forward<F>(f)();
    } catch (...) {
      if (!error_) error_ = std::current_exception();
      throw nlopt::forced_stop();
    }
  }

  // Whether the calling thread is inside a guarded objective (for the tests, which cancel there).
  static bool active() { return depth() > 0; }

  // opt.optimize(x, value): rethrows the objective's exception, if any, once NLopt has returned;
  // NLopt's own exceptions (round-off, forced stop, failure) end the optimisation quietly.
  void optimize(nlopt::opt* opt, std::vector<double>* x, double* value) {
    try {
      opt->optimize(*x, *value);
    } catch (const std::exception&) {
      if (!error_) return;  // NLopt's own end: the caller keeps the best point evaluated
    }
    if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
  }

 private:
  static int& depth() {
    thread_local int d = 0;
    return d;
  }
  std::exception_ptr error_;
};

}  // namespace sphereset::detail
