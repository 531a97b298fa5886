// Error reporting for library calls: a value or an Error with a one-line message.
// Library code never throws on bad data and never aborts; assertions guard programmer
// errors only.
#pragma once

#include <cassert>
#include <string>
#include <utility>
#include <variant>

namespace sphereset {

// What went wrong, coarse enough for a command-line tool to map to an exit code.
enum class ErrorCode {
  kInvalidArgument,  // an option out of range
  kUnreadable,       // the file is missing, unreadable or not in a known format
  kInvalidData,      // the file parsed but holds bad data (NaN, bad index, empty)
  kNotSolid,         // the mesh is not a closed manifold solid
  kWriteFailed,      // the output could not be written
};

struct Error {
  ErrorCode code;
  std::string message;  // one line, names the file and the problem where known
};

// A minimal std::expected (C++23) stand-in: holds either a T or an Error.
template <class T>
class [[nodiscard]] Expected {
 public:
  Expected(T value) : v_(std::move(value)) {}      // NOLINT: implicit by design
  Expected(Error error) : v_(std::move(error)) {}  // NOLINT: implicit by design

  bool ok() const { return v_.index() == 0; }
  explicit operator bool() const { return ok(); }

  T& value() & {
    assert(ok());
    return std::get<0>(v_);
  }
  const T& value() const& {
    assert(ok());
    return std::get<0>(v_);
  }
  T&& value() && {
    assert(ok());
    return std::get<0>(std::move(v_));
  }
  T* operator->() { return &value(); }
  const T* operator->() const { return &value(); }
  T& operator*() & { return value(); }
  const T& operator*() const& { return value(); }

  const Error& error() const {
    assert(!ok());
    return std::get<1>(v_);
  }

 private:
  std::variant<T, Error> v_;
};

// Status for calls that return nothing on success.
class [[nodiscard]] Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error)), ok_(false) {}  // NOLINT: implicit by design
  bool ok() const { return ok_; }
  explicit operator bool() const { return ok_; }
  const Error& error() const {
    assert(!ok_);
    return error_;
  }

 private:
  Error error_{ErrorCode::kInvalidArgument, {}};
  bool ok_ = true;
};

}  // namespace sphereset
